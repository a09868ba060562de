// The tessellated surface: welded output is a closed, oriented 2-manifold with the input's
// topology; unwelded output keeps every patch's own grid.
#include <gtest/gtest.h>

#include "stitch/mesh/validate.hpp"
#include "stitch/tess/tessellate.hpp"
#include "test_support.hpp"

namespace stitch {
namespace {

PolygonSoup as_soup(const TessellatedMesh& s) {
  PolygonSoup soup;
  soup.positions = s.positions;
  for (const auto& q : s.quads) soup.faces.push_back({q[0], q[1], q[2], q[3]});
  return soup;
}

Vec3 quad_normal(const TessellatedMesh& s, const std::array<int, 4>& q) {
  return (s.positions[q[2]] - s.positions[q[0]]).cross(s.positions[q[3]] - s.positions[q[1]]);
}

void expect_welded_surface_ok(const HalfedgeMesh& input, Method method, int resolution,
                              const std::string& name) {
  const Surface surface(input, method);
  const TessellatedMesh s = tessellate(input, surface, {resolution, true});
  for (int i = 0; i < s.num_vertices(); ++i) {
    ASSERT_TRUE(s.positions[i].allFinite()) << name;
    ASSERT_TRUE(s.normals[i].allFinite()) << name;
  }
  // Closed, manifold and consistently oriented: build_mesh refuses anything else.
  const HalfedgeMesh out = build_mesh(as_soup(s));
  const TopologyStats a = topology_stats(input), b = topology_stats(out);
  EXPECT_EQ(b.euler, a.euler) << name;
  EXPECT_EQ(b.components, a.components) << name;
  EXPECT_EQ(b.genus, a.genus) << name;
  // Every sample is used: nothing dangles.
  EXPECT_EQ(out.num_vertices(), s.num_vertices()) << name;
  // The quads wind the way the analytic normals point.
  int against = 0;
  for (const auto& q : s.quads) {
    const Vec3 n = quad_normal(s, q);
    Vec3 vn = Vec3::Zero();
    for (int v : q) vn += s.normals[v];
    if (n.dot(vn) <= 0) ++against;
  }
  EXPECT_EQ(against, 0) << name;
}

TEST(Tessellate, WeldedOutputIsAClosedOrientedManifoldWithTheInputsTopology) {
  for (const std::string& name : test::closed_opensubdiv_shapes())
    expect_welded_surface_ok(read_mesh(test::opensubdiv_shape(name)), Method::mdc, 4, name);
  for (const char* name :
       {"cube.obj", "tetrahedron.obj", "torus.obj", "cube_hole.obj", "two_cubes.obj"})
    expect_welded_surface_ok(read_mesh(test::example_path(name)), Method::mdc, 3, name);
  expect_welded_surface_ok(test::cube_mesh(), Method::asc, 1, "cube asc, resolution 1");
}

TEST(Tessellate, NormalsPointOutwardOnAConvexShape) {
  const HalfedgeMesh cube = test::cube_mesh();
  const TessellatedMesh s = tessellate(cube, Surface(cube, Method::mdc), {6, true});
  for (int i = 0; i < s.num_vertices(); ++i) EXPECT_GT(s.normals[i].dot(s.positions[i]), 0);
}

TEST(Tessellate, UnweldedKeepsEveryPatchGridWithItsParameters) {
  const HalfedgeMesh tet = test::tetrahedron_mesh();
  const int n = 5;
  const TessellatedMesh s = tessellate(tet, Surface(tet, Method::mdc), {n, false});
  ASSERT_EQ(s.num_vertices(), 12 * (n + 1) * (n + 1));
  ASSERT_EQ(static_cast<int>(s.quads.size()), 12 * n * n);
  for (int i = 0; i < s.num_vertices(); ++i) {
    const int k = i % ((n + 1) * (n + 1));
    EXPECT_DOUBLE_EQ(s.uv[i].x(), static_cast<double>(k / (n + 1)) / n);
    EXPECT_DOUBLE_EQ(s.uv[i].y(), static_cast<double>(k % (n + 1)) / n);
  }
  // Samples near an extraordinary corner come from deeper sub-patches.
  int deepest = 0;
  for (int l : s.level) deepest = std::max(deepest, l);
  EXPECT_GE(deepest, 3);  // (1/5, 0) needs 3 splits before it leaves the corner's child
}

TEST(Tessellate, RefusesAResolutionBelowOne) {
  const HalfedgeMesh tet = test::tetrahedron_mesh();
  EXPECT_THROW(tessellate(tet, Surface(tet, Method::mdc), {0, true}), Error);
}

}  // namespace
}  // namespace stitch
