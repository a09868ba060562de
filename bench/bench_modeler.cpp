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
//   modeler_first_insert_edge   the same edit as modeler_insert_edge, but the first one after
//                         loading the mesh (the surface rebuilt, as the modeler does at load;
//                         not timed): the edit that must find room in the surface's arrays
//                         (slot_capacity_for) instead of moving all of them.
// Counters: faces, patches (corners) in the mesh, recomputed = patches re-evaluated per edit.
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <memory>
#include <string>

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

/// insert-edge across the diagonal of the torus's middle face.
std::string diagonal_of_middle_face(const HalfedgeMesh& mesh) {
  const Face f(mesh.num_faces() / 2);
  const auto loop = mesh.face_loop(f);
  return fmt::format("insert-edge {}@{} {}@{}", mesh.origin(loop[0]).idx + 1, f.idx + 1,
                     mesh.origin(loop[2]).idx + 1, f.idx + 1);
}

/// `surface_only`: time just IncrementalSurface::update, not the document's side of the edit.
void insert_edge(benchmark::State& state, bool surface_only) {
  Document doc(torus_for(state.range(0)));
  IncrementalSurface live;
  live.rebuild(doc.mesh(), doc.kgon_options(), Method::mdc, 8);
  const std::string line = diagonal_of_middle_face(doc.mesh());
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

void modeler_first_insert_edge(benchmark::State& state) {
  const HalfedgeMesh torus = torus_for(state.range(0));
  const std::string line = diagonal_of_middle_face(torus);
  SurfaceUpdateStats last;
  for (auto _ : state) {
    state.PauseTiming();
    // Held outside the timed scope: freeing the surface's arrays is not the edit's cost.
    auto doc = std::make_unique<Document>(torus);
    auto live = std::make_unique<IncrementalSurface>();
    live->rebuild(doc->mesh(), doc->kgon_options(), Method::mdc, 8);
    state.ResumeTiming();
    last = live->update(doc->mesh(), doc->kgon_options(), doc->apply_operation(line));
    benchmark::DoNotOptimize(live->tessellation().positions.data());
    state.PauseTiming();
    live.reset();
    doc.reset();
    state.ResumeTiming();
  }
  state.counters["faces"] = static_cast<double>(torus.num_faces());
  state.counters["recomputed"] = last.recomputed_patches;
}

}  // namespace

BENCHMARK(modeler_vertex_move)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(modeler_insert_edge)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(modeler_insert_edge_surface_only)
    ->Arg(1000)
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond);
// Each iteration loads and rebuilds untimed (about half a second at 10k faces).
BENCHMARK(modeler_first_insert_edge)
    ->Arg(1000)
    ->Arg(10000)
    ->Iterations(8)
    ->Unit(benchmark::kMillisecond);
