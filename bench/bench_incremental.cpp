// stitch::IncrementalSurface after every vertex moved and the connectivity stayed (a deforming
// animation): update_positions, which keeps the layout (uv, patch ids, quads) and recomputes the
// K-gons, nets and samples, against rebuild, which builds everything again. Resolution 8,
// unwelded (as the modeler's renderer takes it). The mesh alternates between two states of the
// same connectivity (the torus, and the torus with every vertex moved by a fixed-seed random
// offset), so every patch changes in every iteration.
//   incremental_update_positions/kind   IncrementalSurface::update_positions
//   incremental_rebuild/kind            IncrementalSurface::rebuild
// kind 0: quad torus, 1: tris+quads torus (bench_meshes.hpp), both of about 10k faces.
#include <benchmark/benchmark.h>

#include <array>
#include <random>

#include "bench_meshes.hpp"
#include "stitch/tess/incremental_surface.hpp"

namespace {

using namespace stitch;

constexpr int kResolution = 8;

std::array<HalfedgeMesh, 2> two_states(bench::MeshKind kind) {
  const HalfedgeMesh& mesh = bench::bench_mesh(kind, 10000);
  HalfedgeMesh moved = mesh;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> step(-0.02, 0.02);
  for (Vertex v : moved.vertices()) moved.position(v) += Vec3(step(rng), step(rng), step(rng));
  return {mesh, moved};
}

void incremental_update_positions(benchmark::State& state) {
  const auto kind = static_cast<bench::MeshKind>(state.range(0));
  const auto meshes = two_states(kind);
  IncrementalSurface live;
  live.rebuild(meshes[0], {}, Method::mdc, kResolution);
  int step = 0;
  SurfaceUpdateStats last;
  for (auto _ : state) {
    last = live.update_positions(meshes[++step % 2], {});
    benchmark::DoNotOptimize(live.tessellation().positions.data());
  }
  state.SetLabel(bench::mesh_label(kind, meshes[0]));
  state.counters["patches"] = live.num_patches();
  state.counters["recomputed"] = last.recomputed_patches;
}

void incremental_rebuild(benchmark::State& state) {
  const auto kind = static_cast<bench::MeshKind>(state.range(0));
  const auto meshes = two_states(kind);
  IncrementalSurface live;
  int step = 0;
  for (auto _ : state) {
    live.rebuild(meshes[++step % 2], {}, Method::mdc, kResolution);
    benchmark::DoNotOptimize(live.tessellation().positions.data());
  }
  state.SetLabel(bench::mesh_label(kind, meshes[0]));
  state.counters["patches"] = live.num_patches();
}

BENCHMARK(incremental_update_positions)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(incremental_rebuild)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
