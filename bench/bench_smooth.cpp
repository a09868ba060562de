// `stitch smooth` end to end, stage by stage, as the command runs it: read the input file, build
// the surface, then tessellate and write (streamed: evaluated block by block while writing).
// Meshes: quad tori and tris+quads tori of about 10k and 100k faces, written at resolution 8 as
// binary PLY (doubles, and floats as --float writes them), OBJ, STL and .glb into a temporary
// folder.
//
// Counters (seconds per iteration, wall clock): read, surface, tessellate+write (the streamed
// stage), and evaluate_only, the same evaluation in the same blocks on all cores with nothing
// kept or written. write_share = (tessellate+write - evaluate_only) / total is the
// share of the whole command that writing costs. Mvertices/s counts output vertices. peak_GB: the
// process's peak resident size (run one case per process for its own).
#include <benchmark/benchmark.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>

#include "bench_meshes.hpp"
#include "stitch/eval/surface.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/output/output.hpp"
#include "stitch/tess/export.hpp"
#include "stitch/tess/tessellate.hpp"
#include "tess/layout.hpp"

namespace {

using namespace stitch::bench;
using Clock = std::chrono::steady_clock;

constexpr int kResolution = 8;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Formats: 0 binary PLY (doubles), 1 OBJ, 2 STL, 3 binary PLY with --float, 4 .glb.
const char* extension(int format) {
  switch (format) {
    case 1:
      return ".obj";
    case 2:
      return ".stl";
    case 4:
      return ".glb";
    default:
      return ".ply";
  }
}

void BM_smooth(benchmark::State& state) {
  const auto kind = static_cast<MeshKind>(state.range(0));
  const stitch::HalfedgeMesh& generated = bench_mesh(kind, static_cast<int>(state.range(1)));
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("stitch-bench-smooth-" + std::to_string(getpid()));
  std::filesystem::create_directories(folder);
  const std::string input = (folder / "input.obj").string();
  stitch::write_mesh(input, generated);
  const std::string output =
      (folder / (std::string("smooth") + extension(state.range(2)))).string();
  const stitch::MeshFileFormat format = *stitch::output_format(output).mesh_format;

  double read = 0, surface_time = 0, write = 0, evaluate_only = 0;
  std::int64_t vertices = 0;
  for (auto _ : state) {
    auto start = Clock::now();
    const stitch::HalfedgeMesh mesh = stitch::read_mesh(input);
    read += seconds_since(start);
    start = Clock::now();
    const stitch::Surface surface(mesh, stitch::Method::mdc);
    surface_time += seconds_since(start);
    start = Clock::now();
    stitch::SurfaceFileOptions file;
    file.single_precision = state.range(2) == 3;
    vertices +=
        stitch::write_smooth_surface(output, format, mesh, surface, kResolution, file).vertices;
    write += seconds_since(start);

    state.PauseTiming();
    start = Clock::now();
    const stitch::TessellationLayout layout(mesh, surface.corners(), kResolution, true);
    tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, layout.num_vertices(), 16384),
                      [&](const tbb::blocked_range<std::int64_t>& r) {
                        std::vector<stitch::Vec3> positions(r.size()), normals(r.size());
                        layout.evaluate(surface, r.begin(), r.end(), positions.data(),
                                        normals.data());
                        benchmark::DoNotOptimize(positions.data());
                      });
    evaluate_only += seconds_since(start);
    state.ResumeTiming();
  }
  std::filesystem::remove_all(folder);

  const double n = static_cast<double>(state.iterations());
  const double total = read + surface_time + write;
  state.counters["read"] = read / n;
  state.counters["surface"] = surface_time / n;
  state.counters["tessellate+write"] = write / n;
  state.counters["evaluate_only"] = evaluate_only / n;
  state.counters["write_share"] = std::max(0.0, write - evaluate_only) / total;
  state.counters["Mvertices/s"] = static_cast<double>(vertices) / total / 1e6;
  state.counters["peak_GB"] = peak_rss_gb();
  state.SetLabel(mesh_label(kind, generated) + ", " + extension(state.range(2)) +
                 (state.range(2) == 3 ? " --float" : ""));
}

BENCHMARK(BM_smooth)
    ->ArgNames({"mesh", "faces", "format"})
    ->ArgsProduct({{quad_torus, mixed_torus}, {10000, 100000}, {0, 1, 2, 3, 4}})
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(1);

}  // namespace
