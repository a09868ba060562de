// The PatchSampler keeps the splits of extraordinary nets between points: its results must be
// Surface::evaluate's to the last bit, whatever order the points come in.
#include <gtest/gtest.h>

#include <random>

#include "eval/patch_sampler.hpp"
#include "stitch/topology/operation.hpp"
#include "stitch/topology/primitives.hpp"

namespace stitch {
namespace {

TEST(PatchSampler, GivesExactlySurfaceEvaluateInAnyOrder) {
  // Valence-3 and valence-5 vertices, a 10-sided face that runs along an edge twice, triangles.
  HalfedgeMesh mesh = make_cube();
  apply_operation(mesh, "insert-edge 1@1 5@2");
  apply_operation(mesh, "insert-edge 2@3 5@3");
  for (const Method method : {Method::mdc, Method::asc}) {
    const Surface surface(mesh, method);
    PatchSampler sampler(surface);
    std::mt19937 random(7);
    const auto& corners = surface.corners();
    std::uniform_int_distribution<size_t> pick(0, corners.size() - 1);
    std::uniform_int_distribution<int> grid(0, 16);
    std::uniform_real_distribution<double> anywhere(0.0, 1.0);
    int extraordinary = 0;
    for (int trial = 0; trial < 4000; ++trial) {
      // Runs of points on one patch, on a few patches in turn, and anywhere; grid points (as a
      // tessellation asks) and arbitrary ones, including ones deep near the corners.
      const Corner c = corners[trial % 3 == 0 ? pick(random) : (trial / 40) % corners.size()];
      double u = trial % 2 == 0 ? grid(random) / 16.0 : anywhere(random);
      double v = trial % 5 == 0 ? std::ldexp(1.0, -grid(random) * 3) : grid(random) / 16.0;
      if (trial % 7 == 0) std::swap(u, v);
      const SurfacePoint expected = surface.evaluate(c, u, v);
      const SurfacePoint got = sampler.evaluate(c, u, v);
      ASSERT_EQ(got.position, expected.position) << c.idx << " " << u << " " << v;
      ASSERT_EQ(got.du, expected.du);
      ASSERT_EQ(got.dv, expected.dv);
      ASSERT_EQ(got.normal, expected.normal);
      ASSERT_EQ(got.level, expected.level);
      extraordinary += !surface.bezier().nets[c.idx].regular();
    }
    EXPECT_GT(extraordinary, 1000) << "most points should be on extraordinary patches";
  }
}

TEST(PatchSampler, GridPointsAreExactlySurfaceEvaluate) {
  HalfedgeMesh mesh = make_cube();
  apply_operation(mesh, "insert-edge 1@1 5@2");
  apply_operation(mesh, "insert-edge 2@3 5@3");
  apply_operation(mesh, "vertex-insertion");  // regular patches beside extraordinary ones
  for (const Method method : {Method::mdc, Method::asc, Method::cc})
    for (const int n : {1, 3, 8}) {
      const Surface surface(mesh, method);
      PatchSampler sampler(surface, n);
      // Patch by patch, then alternating between two patches, as the tessellation asks.
      const auto& corners = surface.corners();
      for (size_t k = 0; k < corners.size(); ++k)
        for (int i = 0; i <= n; ++i)
          for (int j = 0; j <= n; ++j)
            for (const Corner c : {corners[k], corners[(k * 7 + 3) % corners.size()]}) {
              const SurfacePoint expected =
                  surface.evaluate(c, static_cast<double>(i) / n, static_cast<double>(j) / n);
              const SurfacePoint got = sampler.evaluate_grid(c, i, j);
              ASSERT_EQ(got.position, expected.position) << to_string(method) << " " << c.idx;
              ASSERT_EQ(got.du, expected.du);
              ASSERT_EQ(got.dv, expected.dv);
              ASSERT_EQ(got.normal, expected.normal);
              ASSERT_EQ(got.level, expected.level);
            }
    }
}

TEST(PatchSampler, BlocksAreExactlySurfaceEvaluateAndStayInTheirPlaces) {
  HalfedgeMesh mesh = make_cube();
  apply_operation(mesh, "insert-edge 1@1 5@2");
  apply_operation(mesh, "insert-edge 2@3 5@3");
  apply_operation(mesh, "vertex-insertion");
  for (const Method method : {Method::mdc, Method::asc, Method::cc})
    for (const int n : {1, 3, 5, 8, 16}) {
      const Surface surface(mesh, method);
      PatchSampler sampler(surface, n);
      const auto& corners = surface.corners();
      // The whole grid, its interior, one row, one column, a corner sample; the stride leaves a
      // gap after each row that must stay as it was.
      const std::vector<std::array<int, 4>> blocks = {
          {0, n, 0, n}, {1, n - 1, 1, n - 1}, {n, n, 0, n}, {0, n, n / 2, n / 2}, {0, 0, n, n}};
      for (size_t k = 0; k < corners.size(); ++k)
        for (const auto& [i0, i1, j0, j1] : blocks) {
          if (i1 < i0 || j1 < j0) continue;
          const int stride = j1 - j0 + 3;
          const size_t size = static_cast<size_t>(i1 - i0 + 1) * stride;
          const Vec3 unset = Vec3::Constant(std::nan(""));
          std::vector<Vec3> positions(size, unset), normals(size, unset);
          std::vector<int> levels(size, -1);
          sampler.evaluate_block(corners[k], i0, i1, j0, j1,
                                 {positions.data(), normals.data(), levels.data(), stride});
          for (int i = i0; i <= i1; ++i)
            for (int j = j0; j < j0 + stride; ++j) {
              const size_t at = static_cast<size_t>(i - i0) * stride + (j - j0);
              if (j > j1) {
                ASSERT_TRUE(positions[at].hasNaN() && normals[at].hasNaN() && levels[at] == -1);
                continue;
              }
              const SurfacePoint expected = surface.evaluate(corners[k], static_cast<double>(i) / n,
                                                             static_cast<double>(j) / n);
              ASSERT_EQ(positions[at], expected.position)
                  << to_string(method) << " n=" << n << " corner " << corners[k].idx << " (" << i
                  << ", " << j << ")";
              ASSERT_EQ(normals[at], expected.normal);
              ASSERT_EQ(levels[at], expected.level);
            }
        }
    }
}

}  // namespace
}  // namespace stitch
