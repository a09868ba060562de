// Checks of stitch::IncrementalSurface against a from-scratch build, shared by the core's tests
// (test_incremental_surface.cpp) and the modeler's (edits through its Document). The comparisons
// are exact (==): the incremental path runs the same code on the same numbers as a rebuild, so
// any difference is a missed or wrong update, not rounding.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "stitch/tess/incremental_surface.hpp"
#include "stitch/tess/tessellate.hpp"

namespace stitch::test {

/// The surface's live blocks equal tessellate(..., welded = false) of `fresh` (on `mesh`), sample
/// for sample and quad for quad, and its nets equal the fresh ones.
inline void expect_same_as_surface(const IncrementalSurface& live, const HalfedgeMesh& mesh,
                                   const Surface& fresh) {
  TessellationOptions t;
  t.resolution = live.resolution();
  t.welded = false;
  t.uv = t.patch = t.level = true;
  const TessellatedMesh expected = tessellate(mesh, fresh, t);
  const TessellatedMesh& got = live.tessellation();
  // Live corner k's block in `expected` is corner c's slot in `got` (blocks indexed by corner).
  const int per = live.vertices_per_patch(), per_quads = live.quads_per_patch();
  const auto corners = mesh.patch_corners();
  ASSERT_EQ(expected.num_vertices(), static_cast<int>(corners.size()) * per);
  ASSERT_EQ(got.num_vertices(), mesh.halfedge_capacity() * per);
  ASSERT_EQ(live.corners(), corners);
  int mismatches = 0;
  for (size_t k = 0; k < corners.size(); ++k) {
    const int a = static_cast<int>(k) * per, b = corners[k].idx * per;
    for (int s = 0; s < per; ++s) {
      const bool same =
          got.positions[b + s] == expected.positions[a + s] &&
          got.normals[b + s] == expected.normals[a + s] && got.uv[b + s] == expected.uv[a + s] &&
          got.patch[b + s] == expected.patch[a + s] && got.level[b + s] == expected.level[a + s];
      mismatches += same ? 0 : 1;
    }
    for (int q = 0; q < per_quads; ++q)
      for (int i = 0; i < 4; ++i)
        mismatches += got.quads[corners[k].idx * per_quads + q][i] - b ==
                              expected.quads[k * per_quads + q][i] - a
                          ? 0
                          : 1;
  }
  EXPECT_EQ(mismatches, 0);
  for (Corner c : corners) EXPECT_TRUE(live.nets()[c.idx] == fresh.bezier().nets[c.idx]);
}

/// The same against a fresh Surface(mesh, live.method(), options).
inline void expect_same_as_rebuild(const IncrementalSurface& live, const HalfedgeMesh& mesh,
                                   const KgonOptions& options) {
  expect_same_as_surface(live, mesh, Surface(mesh, live.method(), options));
}

/// Applies `change` (already made to `mesh` and `options`) and checks that the recomputed set is
/// exactly the set of live corners whose nets differ between before and a from-scratch rebuild
/// after (a corner without a live patch before counts as changed), and that the result equals a
/// rebuild.
inline void check_update(IncrementalSurface& live, const HalfedgeMesh& mesh,
                         const KgonOptions& options, const SurfaceChange& change) {
  const std::vector<ControlNet> before = live.nets();
  const std::vector<Corner> live_before = live.corners();
  const SurfaceUpdateStats stats = live.update(mesh, options, change);
  const std::vector<ControlNet> fresh = build_control_nets(mesh, build_kgons(mesh, options));
  std::vector<Corner> changed;
  for (Corner c : mesh.patch_corners()) {
    const bool existed = std::binary_search(live_before.begin(), live_before.end(), c);
    if (!existed || before[c.idx] != fresh[c.idx]) changed.push_back(c);
  }
  if (live.method() != Method::cc) {
    EXPECT_EQ(live.recomputed(), changed);
    EXPECT_EQ(stats.recomputed_patches, static_cast<int>(changed.size()));
    EXPECT_FALSE(stats.full);
  }
  expect_same_as_rebuild(live, mesh, options);
}

}  // namespace stitch::test
