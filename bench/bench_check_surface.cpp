// stitch::check_surface on a whole tessellated surface, what `stitch check-surface` and
// `stitch smooth --check` run: folds and orientation over the shared edges, then crossings from a
// uniform grid. The mixed torus (bench_meshes.hpp) of about 1k faces at resolution 8, about
// 600k triangles; the tessellation is made once, outside the loop.
//   check_surface/0   every check
//   check_surface/1   the edges only: crossings_only_when_unfolded on a surface made to fold by
//                     one vertex pushed through the torus, as unfold_tubes' search checks a
//                     setting that folds
// and check_surface(mesh, surface, 8), what `stitch smooth --check` runs, on the quad tori of
// about 10k and 100k faces (the surface built outside the loop; peak_GB: the process's peak
// resident size, its own when it is the only case run).
#include <benchmark/benchmark.h>

#include "bench_meshes.hpp"
#include "stitch/analysis/surface_check.hpp"
#include "stitch/eval/surface.hpp"
#include "stitch/tess/tessellate.hpp"

namespace {

using namespace stitch;

void check_surface(benchmark::State& state) {
  const bool folding = state.range(0) == 1;
  HalfedgeMesh mesh = bench::bench_mesh(bench::mixed_torus, 1000);
  if (folding) mesh.position(Vertex(0)) *= 0.2;
  TessellationOptions t;
  t.resolution = 8;
  const TriangleSoup soup = triangulate(tessellate(mesh, Surface(mesh, Method::mdc), t));
  SurfaceCheckOptions options;
  options.crossings_only_when_unfolded = folding;
  int folds = 0;
  for (auto _ : state) {
    const SurfaceCheckReport report = stitch::check_surface(soup, options);
    folds = report.folds;
    benchmark::DoNotOptimize(report.triangles);
  }
  state.counters["triangles"] = static_cast<double>(soup.triangles.size());
  state.counters["folds"] = folds;
  state.SetLabel(bench::mesh_label(bench::mixed_torus, mesh));
}
BENCHMARK(check_surface)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void check_surface_patches(benchmark::State& state) {
  const HalfedgeMesh& mesh = bench::bench_mesh(bench::quad_torus, static_cast<int>(state.range(0)));
  const Surface surface(mesh, Method::mdc);
  int triangles = 0;
  for (auto _ : state) {
    const SurfaceCheckReport report = stitch::check_surface(mesh, surface, 8);
    triangles = report.triangles;
    benchmark::DoNotOptimize(report.folds);
  }
  state.counters["triangles"] = triangles;
  state.counters["peak_GB"] = bench::peak_rss_gb();
  state.SetLabel(bench::mesh_label(bench::quad_torus, mesh));
}
BENCHMARK(check_surface_patches)
    ->ArgName("faces")
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(1);

}  // namespace
