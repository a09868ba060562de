// Adaptive tessellation (--tolerance): per-side rates shared by both patches, transition strips.
#include <gtest/gtest.h>

#include <map>
#include <utility>

#include "cli_run.hpp"
#include "stitch/analysis/surface_check.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/tess/adaptive.hpp"
#include "tess/adaptive.hpp"
#include "test_support.hpp"

namespace stitch {
namespace {

using detail::zip_strip;

/// Twice the signed area in the strip's (along, across) plane: outer chain at across 0, inner
/// at across 1, both running along [0, 1].
double strip_area(int outer, int inner, const std::array<detail::StripCorner, 3>& t) {
  std::array<Eigen::Vector2d, 3> p;
  for (int k = 0; k < 3; ++k)
    p[k] = t[k][0] == 0 ? Eigen::Vector2d(static_cast<double>(t[k][1]) / outer, 0.0)
                        : Eigen::Vector2d(static_cast<double>(t[k][1] + 1) / (inner + 1), 1.0);
  const Eigen::Vector2d a = p[1] - p[0], b = p[2] - p[0];
  return a.x() * b.y() - a.y() * b.x();
}

TEST(AdaptiveStrip, ZipsEverySegmentOnceAndTilesTheTrapezoid) {
  for (int outer = 1; outer <= 9; ++outer)
    for (int inner = 1; inner <= 9; ++inner) {
      const auto tris = zip_strip(outer, inner);
      ASSERT_EQ(static_cast<int>(tris.size()), outer + inner - 1);
      // Every triangle has exactly one edge on a chain, each chain segment is used once, and the
      // areas add up to the trapezoid's: no gap, no overlap.
      std::map<std::pair<int, int>, int> used;
      double area = 0;
      for (const auto& t : tris) {
        const double a = strip_area(outer, inner, t);
        EXPECT_GT(a, 0) << outer << " " << inner;
        area += a;
        for (int e = 0; e < 3; ++e) {
          const auto& p = t[e];
          const auto& q = t[(e + 1) % 3];
          if (p[0] == q[0]) {
            EXPECT_EQ(std::abs(p[1] - q[1]), 1);
            ++used[{p[0], std::min(p[1], q[1])}];
          }
        }
      }
      EXPECT_EQ(static_cast<int>(used.size()), outer + inner - 1);
      for (const auto& [segment, count] : used) EXPECT_EQ(count, 1);
      const double trapezoid = 1.0 + (inner - 1.0) / (inner + 1.0);  // twice (1 + top) / 2
      EXPECT_NEAR(area, trapezoid, 1e-12) << outer << " " << inner;
    }
}

/// Every directed edge once and its reverse once (closed) or at most once (boundary).
void expect_consistent_manifold(const AdaptiveMesh& m, bool closed) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : m.triangles) {
    EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]);
    for (int e = 0; e < 3; ++e) ++directed[{t[e], t[(e + 1) % 3]}];
  }
  int open = 0;
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second << " runs one way twice";
    if (!directed.contains({edge.second, edge.first})) ++open;
  }
  if (closed) {
    EXPECT_EQ(open, 0) << "edges used by one triangle only: cracks";
  }
  // Every vertex is used, so no sample is left dangling in a crack.
  std::vector<char> used(m.positions.size(), 0);
  for (const auto& t : m.triangles)
    for (int v : t) used[v] = 1;
  EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0);
}

TEST(Adaptive, CubeHoleIsWatertightOnTheSurfaceAndCheaperThanResolution16) {
  const HalfedgeMesh mesh = read_mesh(test::example_path("cube_hole.obj"));
  for (const Method method : {Method::mdc, Method::asc, Method::cc}) {
    SCOPED_TRACE(to_string(method));
    const Surface surface(mesh, method);
    const AdaptiveMesh m = tessellate_adaptive(mesh, surface);  // default tolerance 1e-3
    expect_consistent_manifold(m, true);
    // Closed with the input's genus (1): V - E + F = 0, E = 3F / 2.
    const auto f = static_cast<std::int64_t>(m.triangles.size());
    EXPECT_EQ(m.num_vertices() - 3 * f / 2 + f, 0);
    for (int v = 0; v < m.num_vertices(); ++v) {
      const SurfacePoint p = surface.evaluate(Corner(m.patch[v]), m.uv[v].x(), m.uv[v].y());
      ASSERT_LE((p.position - m.positions[v]).norm(), 1e-12) << v;
      ASSERT_NEAR(m.normals[v].norm(), 1.0, 1e-12);
      // AS&C patches are not G1 at extraordinary points: the mean normal may differ there.
      if (method != Method::asc) {
        ASSERT_GT(m.normals[v].dot(p.normal), 0.99) << v;
      }
    }
    const auto uniform16 = static_cast<std::int64_t>(surface.corners().size()) * 16 * 16 * 2;
    EXPECT_LT(f, uniform16);
    EXPECT_GE(m.min_rate, 1);
    EXPECT_LE(m.max_rate, 64);
    EXPECT_LT(m.min_rate, m.max_rate) << "the cube's flat and curved parts should differ";
    const TriangleSoup s = triangulate(m);
    const SurfaceCheckReport report = check_surface(s);
    EXPECT_EQ(report.folds, 0) << report.describe(s);
    EXPECT_TRUE(report.clean()) << report.describe(s);
  }
}

TEST(Adaptive, TighterToleranceRefinesAndTheRateIsClamped) {
  const HalfedgeMesh mesh = read_mesh(test::example_path("torus.obj"));
  const Surface surface(mesh, Method::mdc);
  size_t previous = 0;
  for (const double tolerance : {1e-2, 1e-3, 1e-4}) {
    const AdaptiveMesh m = tessellate_adaptive(mesh, surface, {tolerance});
    EXPECT_GT(m.triangles.size(), previous) << tolerance;
    previous = m.triangles.size();
    expect_consistent_manifold(m, true);
  }
  const AdaptiveMesh capped = tessellate_adaptive(mesh, surface, {1e-12, 5});
  EXPECT_EQ(capped.min_rate, 5);
  EXPECT_EQ(capped.max_rate, 5);
  // All rates 5: exactly the uniform grid's 2 * 25 triangles per patch.
  EXPECT_EQ(capped.triangles.size(), surface.corners().size() * 50);
  const AdaptiveMesh coarse = tessellate_adaptive(mesh, surface, {1e6});
  EXPECT_EQ(coarse.max_rate, 1);
  EXPECT_EQ(coarse.triangles.size(), surface.corners().size() * 2);
  EXPECT_THROW(tessellate_adaptive(mesh, surface, {0.0}), Error);
}

TEST(Adaptive, OpenMeshKeepsItsBoundaryWithoutCracksInside) {
  const HalfedgeMesh mesh = read_mesh(test::example_path("open_box.obj"));
  const Surface surface(mesh, Method::mdc);
  const AdaptiveMesh m = tessellate_adaptive(mesh, surface, {1e-4});
  expect_consistent_manifold(m, false);
  // One boundary loop (the box's rim): V - E + F = 1 for a disc.
  std::map<std::pair<int, int>, int> undirected;
  for (const auto& t : m.triangles)
    for (int e = 0; e < 3; ++e)
      ++undirected[{std::min(t[e], t[(e + 1) % 3]), std::max(t[e], t[(e + 1) % 3])}];
  const auto e = static_cast<std::int64_t>(undirected.size());
  EXPECT_EQ(m.num_vertices() - e + static_cast<std::int64_t>(m.triangles.size()), 1);
}

TEST(Adaptive, CliWritesTrianglesAndRefusesBothControls) {
  testing::TempFolder folder;
  const std::string in = test::example_path("cube_hole.obj");
  const auto r = testing::stitch_cli(folder, "smooth '" + in + "' -o a.obj --tolerance 1e-3");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("triangles"), std::string::npos) << r.out;
  const HalfedgeMesh back = read_mesh(folder.file("a.obj"));
  EXPECT_EQ(topology_stats(back).genus, 1);
  EXPECT_EQ(topology_stats(back).boundary_loops, 0);
  const auto ply = testing::stitch_cli(folder, "smooth '" + in + "' -o a.ply --tolerance 1e-2");
  EXPECT_EQ(ply.status, 0) << ply.err;
  const auto both =
      testing::stitch_cli(folder, "smooth '" + in + "' -o b.obj --tolerance 1e-3 --resolution 4");
  EXPECT_NE(both.status, 0);
  EXPECT_FALSE(std::filesystem::exists(folder.file("b.obj")));
  const auto glb = testing::stitch_cli(folder, "smooth '" + in + "' -o b.glb --tolerance 1e-3");
  EXPECT_NE(glb.status, 0);
  EXPECT_NE(glb.err.find("tolerance asks a mesh output for adaptive triangles"), std::string::npos)
      << glb.err;
}

}  // namespace
}  // namespace stitch
