// build_surface on a mesh with semi-sharp creases, as `stitch smooth` builds it: every tenth edge
// of the quad torus of about 10k faces tagged with sharpness 2, so the mesh is refined twice
// (uniformly, docs/method.md "Semi-sharp creases") before its K-gons and nets are built.
//   semi_sharp_build/0   untagged, for the ratio
//   semi_sharp_build/1   tagged, refined (the default)
//   semi_sharp_build/2   tagged, rounded (--sharp-from 4: the tags made smooth)
// Counters: patches of the surface, refinement levels.
#include <benchmark/benchmark.h>

#include "bench_meshes.hpp"
#include "stitch/analysis/build_surface.hpp"

namespace {

using namespace stitch;

void semi_sharp_build(benchmark::State& state) {
  const int kind = static_cast<int>(state.range(0));
  HalfedgeMesh mesh = bench::bench_mesh(bench::quad_torus, 10000);
  if (kind > 0)
    for (Edge e : mesh.edges())
      if (e.idx % 10 == 0) mesh.set_sharpness(e, 2.0);
  SurfaceSpec spec;
  if (kind == 2) spec.semi_sharp = SemiSharp::round;
  double patches = 0, levels = 0;
  for (auto _ : state) {
    const BuiltSurface built = build_surface(mesh, spec);
    patches = static_cast<double>(built.surface.corners().size());
    levels = built.refinement.levels;
    benchmark::DoNotOptimize(built.surface.corners().data());
  }
  state.counters["patches"] = patches;
  state.counters["levels"] = levels;
  state.SetLabel(bench::mesh_label(bench::quad_torus, mesh));
}
BENCHMARK(semi_sharp_build)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace
