// stitch::unfold_tubes on one tube whose fitted K-gons fold: the search of the K-gon controls
// (docs/method.md, "Tubes that still fold"), the Bézier surface built once outside the loop and
// the options reset each iteration, so each one searches from the fitted placement again.
//   unfold_tubes/0   prism 16's half twist (insert-edge 1@1 25@2): clean with its fitted K-gons
//                    but its axis blocked; opened by the second setting
//   unfold_tubes/1   prism 4 six high, one step (insert-edge 1@1 6@2): no setting of the grid is
//                    clean (all 396 tried); the descent past it finds one
//   unfold_tubes/2   the same tube with the grid alone (descent_evaluations 0): all 396, none
//                    clean, as /1 was before the descent
//   unfold_tubes/3   prism 12 six high, half twist (insert-edge 1@1 19@2): the grid (none clean)
//                    and the descent, on 74 patches, where the local check's arrays outgrow
//                    what glibc keeps between checks (support/scratch.hpp)
// The counter `settings` is the number of settings checked per search.
#include <benchmark/benchmark.h>

#include "stitch/analysis/unfold_tubes.hpp"
#include "stitch/topology/operation.hpp"
#include "stitch/topology/primitives.hpp"

namespace {

using namespace stitch;

HalfedgeMesh folding_tube(int kind) {
  const int sides[] = {16, 4, 4, 12};
  const char* edits[] = {"insert-edge 1@1 25@2", "insert-edge 1@1 6@2", "insert-edge 1@1 6@2",
                         "insert-edge 1@1 19@2"};
  HalfedgeMesh m = make_prism(sides[kind]);
  if (kind > 0)
    for (Vertex v : m.vertices()) m.position(v).z() *= 3;
  apply_operation(m, edits[kind]);
  return m;
}

void unfold_tubes(benchmark::State& state) {
  const int kind = static_cast<int>(state.range(0));
  const HalfedgeMesh mesh = folding_tube(kind);
  UnfoldTubesOptions search;
  if (kind == 2) search.descent_evaluations = 0;
  BezierSurface surface = build_bezier_surface(mesh);
  const std::vector<Face> tubes = faces_with_two_openings(mesh, {});
  int settings = 0;
  for (auto _ : state) {
    KgonOptions options;
    const auto found = stitch::unfold_tubes(mesh, options, surface, tubes, search);
    settings = found.empty() ? 0 : found[0].settings_tried;
    benchmark::DoNotOptimize(found.data());
    // Back to the fitted K-gons for the next search, not timed.
    state.PauseTiming();
    surface = build_bezier_surface(mesh);
    state.ResumeTiming();
  }
  state.counters["settings"] = settings;
}
BENCHMARK(unfold_tubes)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

}  // namespace
