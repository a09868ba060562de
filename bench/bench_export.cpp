// Exporting the exact surface through write_surface, as `stitch smooth -o x.step` does: the
// bundled cube, OpenSubdiv's catmark_smoothtris0 (80 triangles), a triangle torus of about 1k
// faces and a quad torus of about 10k, to Bézier JSON, STEP and IGES, and the quad torus to .glb
// for comparison. Each benchmark times one whole export from a built Surface (the patch set,
// the faces, the file); counters give the faces written and the file's size. Files go to the
// system's temporary folder and are removed. Run alone with --benchmark_filter=Export.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "bench_meshes.hpp"
#include "stitch/eval/surface.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/output/output.hpp"

namespace {

using namespace stitch;
using namespace stitch::bench;

enum Input : int { cube = 0, smoothtris = 1, triangles_1k = 2, quads_10k = 3 };
constexpr const char* kExtensions[] = {".bez.json", ".step", ".igs", ".glb"};

const HalfedgeMesh& input(int which) {
  static const HalfedgeMesh cube_mesh = read_mesh(STITCH_EXAMPLES_DIR "/cube.obj");
  static const HalfedgeMesh tris_mesh =
      read_mesh(STITCH_OPENSUBDIV_SHAPES_DIR "/catmark_smoothtris0.obj");
  switch (which) {
    case cube:
      return cube_mesh;
    case smoothtris:
      return tris_mesh;
    case triangles_1k:
      return bench_mesh(triangle_torus, 1000);
    default:
      return bench_mesh(quad_torus, 10000);
  }
}

void BM_Export(benchmark::State& state) {
  const int which = static_cast<int>(state.range(0));
  const std::string extension = kExtensions[state.range(1)];
  const HalfedgeMesh& mesh = input(which);
  const Surface surface(mesh, Method::mdc);
  const std::string path =
      (std::filesystem::temp_directory_path() / ("stitch-bench-export" + extension)).string();
  OutputReport report;
  for (auto _ : state) report = write_surface(path, mesh, surface);
  state.counters["faces"] = static_cast<double>(report.faces);
  if (std::filesystem::exists(path))
    state.counters["MB"] = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
  std::filesystem::remove(path);
  const char* names[] = {"cube.obj", "catmark_smoothtris0", "triangle torus", "quad torus"};
  state.SetLabel(std::string(names[which]) + " (" + std::to_string(mesh.num_faces()) + " faces), " +
                 extension);
}

void export_args(benchmark::internal::Benchmark* b) {
  for (int which : {cube, smoothtris, triangles_1k, quads_10k})
    for (int f = 0; f < 3; ++f) b->Args({which, f});
  b->Args({quads_10k, 3});
}

BENCHMARK(BM_Export)
    ->Apply(export_args)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

}  // namespace
