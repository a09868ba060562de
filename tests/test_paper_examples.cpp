// The paper's examples after topology edits, smoothed with the default settings: clean surfaces
// (no self-intersecting, folded or degenerate triangles at resolution 16) and open holes.
#include <gtest/gtest.h>

#include "stitch/analysis/continuity.hpp"
#include "stitch/analysis/surface_check.hpp"
#include "stitch/eval/surface.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/tess/tessellate.hpp"
#include "stitch/topology/operation.hpp"
#include "stitch/topology/primitives.hpp"
#include "test_support.hpp"

namespace stitch {
namespace {

TriangleSoup smooth_triangles(const HalfedgeMesh& mesh, const KgonOptions& kgon = {}) {
  const Surface surface(mesh, Method::mdc, kgon);
  return triangulate(tessellate(mesh, surface, {16, true}));
}

/// The cube with a hole: one edge inserted between vertex 1 of the bottom face and vertex 5 of
/// the top face, directly above it (the README's example).
HalfedgeMesh cube_with_hole() {
  HalfedgeMesh cube = make_cube();
  apply_operation(cube, "insert-edge 1@1 5@2");
  cube.garbage_collection();
  return cube;
}

TEST(PaperExamples, CubeWithAHoleIsCleanAndOpen) {
  const HalfedgeMesh mesh = cube_with_hole();
  const TopologyStats t = topology_stats(mesh);
  ASSERT_EQ(t.genus, 1);
  ASSERT_EQ(t.degree_histogram.at(10), 1);
  const TriangleSoup tris = smooth_triangles(mesh);
  const SurfaceCheckReport r = check_surface(tris);
  EXPECT_TRUE(r.clean()) << r.describe(tris);
  // The line through the centres of the two faces that were joined passes through the hole.
  EXPECT_TRUE(segment_hits(tris, Vec3(0, 0, -3), Vec3(0, 0, 3)).empty());
  // And the surface stays C1 (see test_surface.cpp for the tolerance).
  const ContinuityReport c = analyze_continuity(mesh, Surface(mesh, Method::mdc));
  EXPECT_LT(c.touching_ev.max_deg, 1e-8);
}

TEST(PaperExamples, SectionTwoConstructionAsItStandsPinchesTheHoleShut) {
  // Kept available on purpose (KgonConstruction::doo_sabin): the face K-gon sits at the
  // centroid of the merged loop, inside the tube, and closes the hole.
  KgonOptions section2;
  section2.construction = KgonConstruction::doo_sabin;
  const TriangleSoup tris = smooth_triangles(cube_with_hole(), section2);
  EXPECT_FALSE(segment_hits(tris, Vec3(0, 0, -3), Vec3(0, 0, 3)).empty());
}

TEST(PaperExamples, TwoCubesJoinedByAnEdgeAreClean) {
  const HalfedgeMesh mesh = read_mesh(test::example_path("two_cubes.obj"));
  const TopologyStats t = topology_stats(mesh);
  ASSERT_EQ(t.components, 1);
  ASSERT_EQ(t.genus, 0);
  const TriangleSoup tris = smooth_triangles(mesh);
  const SurfaceCheckReport r = check_surface(tris);
  EXPECT_TRUE(r.clean()) << r.describe(tris);
}

TEST(PaperExamples, CubeWithAHandleFromConnectFacesIsCleanAndOpen) {
  // docs/editing.md: dent the bottom and top faces inwards, then join them with a tube.
  HalfedgeMesh mesh = make_cube();
  for (const char* op : {"extrude-face 1 -0.4 0.5", "extrude-face 2 -0.4 0.5", "connect-faces 1 2"})
    apply_operation(mesh, op);
  mesh.garbage_collection();
  ASSERT_EQ(topology_stats(mesh).genus, 1);
  const TriangleSoup tris = smooth_triangles(mesh);
  const SurfaceCheckReport r = check_surface(tris);
  EXPECT_TRUE(r.clean()) << r.describe(tris);
  EXPECT_TRUE(segment_hits(tris, Vec3(0, 0, -3), Vec3(0, 0, 3)).empty());
}

TEST(PaperExamples, HandlesWithSegmentsOnAnUndentedCubeAreClean) {
  // connect-faces with rings along the path (docs/editing.md): through the cube between opposite
  // faces, with the least twist and every other, and bent between faces that share an edge
  // (twist 0 there would join vertex 1 to itself).
  struct Case {
    const char* op;
    Vec3 axis;  ///< through the two faces' centres, which must pass; zero for a bent tunnel
  };
  const Vec3 z = Vec3::UnitZ(), y = Vec3::UnitY(), bent = Vec3::Zero();
  for (const Case& c : {Case{"connect-faces 1 2 auto 3", z}, Case{"connect-faces 1 2 1 3", z},
                        Case{"connect-faces 1 2 2 3", z}, Case{"connect-faces 1 2 3 3", z},
                        Case{"connect-faces 1 2 auto 2", z}, Case{"connect-faces 1 2 auto 6", z},
                        Case{"connect-faces 3 5 auto 3", y}, Case{"connect-faces 1 3 auto 3", bent},
                        Case{"connect-faces 1 3 2 3", bent}, Case{"connect-faces 1 3 3 4", bent}}) {
    SCOPED_TRACE(c.op);
    HalfedgeMesh mesh = make_cube();
    apply_operation(mesh, c.op);
    mesh.garbage_collection();
    ASSERT_EQ(topology_stats(mesh).genus, 1);
    const TriangleSoup tris = smooth_triangles(mesh);
    const SurfaceCheckReport r = check_surface(tris);
    EXPECT_TRUE(r.clean()) << r.describe(tris);
    if (c.axis != bent) {
      EXPECT_TRUE(segment_hits(tris, -3 * c.axis, 3 * c.axis).empty());
    }
  }
  // One segment on undented faces puts every tube quad on a side face, which folds: that is
  // what the rings are for.
  HalfedgeMesh one_segment = make_cube();
  apply_operation(one_segment, "connect-faces 1 2");
  EXPECT_FALSE(check_surface(smooth_triangles(one_segment)).clean());
}

TEST(PaperExamples, TetrahedronIsClean) {
  const TriangleSoup tris = smooth_triangles(make_tetrahedron());
  const SurfaceCheckReport r = check_surface(tris);
  EXPECT_TRUE(r.clean()) << r.describe(tris);
}

}  // namespace
}  // namespace stitch
