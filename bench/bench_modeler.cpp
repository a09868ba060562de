// The modeler's real-time path: the time from an edit to an updated surface (K-gons, control
// nets, and the re-tessellated patches at resolution 8, unwelded as the renderer takes it), on
// tori of about 1k, 10k and 100k quads (make_torus(m, n)). Not timed: the GPU upload.
//   modeler_vertex_move   one vertex moved (alternately up and back down, so the mesh stays
//                         the same): Document::move_vertices + IncrementalSurface::update, which
//                         rebuilds only the K-gons and nets around the vertex and re-evaluates
//                         only the patches whose nets changed.
//   modeler_insert_edge   insert-edge splitting one quad along its diagonal (apply_operation,
//                         which also recounts the topology for its report, and the document's
//                         undo snapshots) + IncrementalSurface::update, which compares the mesh
//                         with the previous one and rebuilds only around what changed. Undoing it
//                         between iterations is not timed.
//   modeler_insert_edge_surface_only   the same, timing only IncrementalSurface::update.
// Counters: faces, patches (corners) in the mesh, recomputed = patches re-evaluated per edit.
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "stitch/modeler/document.hpp"
#include "stitch/tess/incremental_surface.hpp"
#include "stitch/topology/primitives.hpp"

namespace {

using namespace stitch;
using namespace stitch::modeler;

/// m x n tori: 32x32 = 1024, 100x100 = 10000, 320x320 = 102400 faces.
HalfedgeMesh torus_for(int64_t faces) {
  const int side = faces <= 1024 ? 32 : faces <= 10000 ? 100 : 320;
  return make_torus(side, side);
}

void modeler_vertex_move(benchmark::State& state) {
  Document doc(torus_for(state.range(0)));
  IncrementalSurface live;
  live.rebuild(doc.mesh(), doc.kgon_options(), Method::mdc, 8);
  const Vertex v(doc.mesh().num_vertices() / 2);
  const Vec3 start = doc.mesh().position(v);
  int step = 0;
  SurfaceUpdateStats last;
  for (auto _ : state) {
    const Vec3 p = start + (step++ % 2 == 0 ? 0.05 : 0.0) * Vec3::UnitZ();
    last = live.update(doc.mesh(), doc.kgon_options(), doc.move_vertices({v}, {p}, true));
    benchmark::DoNotOptimize(live.tessellation().positions.data());
  }
  state.counters["faces"] = doc.mesh().num_faces();
  state.counters["patches"] = live.num_patches();
  state.counters["recomputed"] = last.recomputed_patches;
}

/// `surface_only`: time just IncrementalSurface::update, not the document's side of the edit.
void insert_edge(benchmark::State& state, bool surface_only) {
  Document doc(torus_for(state.range(0)));
  IncrementalSurface live;
  live.rebuild(doc.mesh(), doc.kgon_options(), Method::mdc, 8);
  const Face f(doc.mesh().num_faces() / 2);
  const auto loop = doc.mesh().face_loop(f);
  const std::string line =
      fmt::format("insert-edge {}@{} {}@{}", doc.mesh().origin(loop[0]).idx + 1, f.idx + 1,
                  doc.mesh().origin(loop[2]).idx + 1, f.idx + 1);
  // Warm-up: the first edit that adds half-edges grows the tessellation's arrays (a one-time
  // copy of every sample, amortized by the vectors' doubling); later edits fit.
  live.update(doc.mesh(), doc.kgon_options(), doc.apply_operation(line));
  live.update(doc.mesh(), doc.kgon_options(), doc.undo());
  SurfaceUpdateStats last;
  for (auto _ : state) {
    if (surface_only) state.PauseTiming();
    const Change change = doc.apply_operation(line);
    if (surface_only) state.ResumeTiming();
    last = live.update(doc.mesh(), doc.kgon_options(), change);
    benchmark::DoNotOptimize(live.tessellation().positions.data());
    state.PauseTiming();
    live.update(doc.mesh(), doc.kgon_options(), doc.undo());
    state.ResumeTiming();
  }
  state.counters["faces"] = doc.mesh().num_faces();
  state.counters["patches"] = live.num_patches();
  state.counters["recomputed"] = last.recomputed_patches;
}

void modeler_insert_edge(benchmark::State& state) {
  insert_edge(state, false);
}
void modeler_insert_edge_surface_only(benchmark::State& state) {
  insert_edge(state, true);
}

}  // namespace

BENCHMARK(modeler_vertex_move)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(modeler_insert_edge)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(modeler_insert_edge_surface_only)
    ->Arg(1000)
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond);
