// Exporting a model of about 10k faces (bench_meshes.hpp's tori) to each output format: the
// exact patches (expansion, Bézier JSON, STEP, IGES) and the tessellation (glTF binary).
// Each benchmark times the whole export from a built Surface; files go to the system's
// temporary folder and are removed. Run alone with --benchmark_filter=Export.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "bench_meshes.hpp"
#include "stitch/eval/surface.hpp"
#include "stitch/tess/bezier_json.hpp"
#include "stitch/tess/export.hpp"
#include "stitch/tess/patches.hpp"
#if STITCH_WITH_CAD
#include "stitch/cad/cad.hpp"
#endif

namespace {

using namespace stitch;
using namespace stitch::bench;

enum Format : int { patches = 0, json = 1, glb = 2, step = 3, iges = 4 };

const char* format_name(int f) {
  constexpr const char* names[] = {"patches only", ".bez.json", ".glb (resolution 8)", ".step",
                                   ".igs"};
  return names[f];
}

void BM_Export(benchmark::State& state) {
  const auto kind = static_cast<MeshKind>(state.range(0));
  const int format = static_cast<int>(state.range(1));
  const HalfedgeMesh& mesh = bench_mesh(kind, 10000);
  const Surface surface(mesh, Method::mdc);
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("stitch-bench-export" + std::string(format == json   ? ".json"
                                                                 : format == glb  ? ".glb"
                                                                 : format == step ? ".step"
                                                                                  : ".igs")))
                               .string();
  size_t count = 0;
  for (auto _ : state) {
    if (format == glb) {
      write_smooth_surface(path, MeshFileFormat::glb, mesh, surface, 8);
      continue;
    }
    const PatchSet set = bezier_patches(mesh, surface);
    count = set.patches.size();
    state.counters["depth"] = set.depth;
    if (format == json) write_bezier_json(path, set);
#if STITCH_WITH_CAD
    if (format == step || format == iges) {
      cad::quiet_opencascade();
      cad::write_cad(path, mesh, surface, set);
    }
#endif
  }
  if (format != patches && std::filesystem::exists(path))
    state.counters["MB"] = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
  std::filesystem::remove(path);
  if (count > 0) state.counters["patches"] = static_cast<double>(count);
  state.SetLabel(mesh_label(kind, mesh) + ", " + format_name(format));
}

void export_args(benchmark::internal::Benchmark* b) {
  for (int kind : {quad_torus, mixed_torus})
    // STEP and IGES of the mixed torus (some 780k faces) take far longer than the rest
    // together: they are timed on the quad torus only.
    for (int f = patches; f <= (STITCH_WITH_CAD && kind == quad_torus ? iges : glb); ++f)
      b->Args({kind, f});
}

BENCHMARK(BM_Export)
    ->Apply(export_args)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

}  // namespace
