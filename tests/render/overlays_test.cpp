// The CPU side of the renderer on real meshes: overlay geometry, extraordinary points and the
// scene built from the evaluation pipeline (no OpenGL needed).
#include "stitch/render/overlays.hpp"

#include <gtest/gtest.h>

#include "stitch/eval/surface.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/render/options.hpp"
#include "stitch/render/renderer.hpp"
#include "stitch/render/scene.hpp"

namespace stitch {
namespace {

HalfedgeMesh example(const std::string& name) {
  return read_mesh(std::string(STITCH_EXAMPLES_DIR) + "/" + name);
}

TEST(Overlays, CountsMatchTheMesh) {
  const HalfedgeMesh cube = example("cube.obj");
  const KgonSet kgons = build_kgons(cube);
  EXPECT_EQ(mesh_lines(cube).num_segments(), 12);
  // 6 face 4-gons, 8 vertex 3-gons, 12 edge 4-gons.
  EXPECT_EQ(kgon_lines(kgons).num_segments(), 6 * 4 + 8 * 3 + 12 * 4);
  const Surface surface(cube, Method::mdc);
  // Every 4x4 net has 4 rows and 4 columns of 3 segments; one net per corner (24).
  EXPECT_EQ(control_net_lines(surface.bezier().nets, surface.corners()).num_segments(), 24 * 24);
  // input_faces: one degenerate quad per face edge, fanned around the face centre.
  const TessellatedMesh faces = input_faces(cube);
  EXPECT_EQ(faces.quads.size(), 24u);
  EXPECT_EQ(faces.num_vertices(), 6 * 5);
}

TEST(Overlays, ExtraordinaryPointsOfTheCubeAndTheCubeWithAHole) {
  const HalfedgeMesh cube = example("cube.obj");
  const auto corners = extraordinary_points(cube, build_kgons(cube));
  ASSERT_EQ(corners.size(), 8u);
  for (const ExtraordinaryPoint& p : corners) {
    EXPECT_EQ(p.k, 3);
    EXPECT_EQ(p.kind, KgonKind::vertex);
    EXPECT_GT(p.extent, 0.0);
    // By symmetry the limit normal at a cube corner points along the corner's diagonal;
    // 1e-9 is far above the round-off of the K-gon plane fit and far below any real tilt.
    const Vec3 diagonal = cube.position(Vertex(p.element)).normalized();
    EXPECT_NEAR(p.normal.dot(diagonal), 1.0, 1e-9);
  }
  // cube_hole: 6 vertices of valence 3 and the 10-sided face.
  const HalfedgeMesh hole = example("cube_hole.obj");
  const auto points = extraordinary_points(hole, build_kgons(hole));
  EXPECT_EQ(points.size(), 7u);
  const ExtraordinaryPoint& highest = highest_valence_point(points);
  EXPECT_EQ(highest.k, 10);
  EXPECT_EQ(highest.kind, KgonKind::face);
  EXPECT_THROW(highest_valence_point({}), UsageError);
}

TEST(Scene, UnweldedTessellationHasOneVertexBlockPerPatch) {
  const HalfedgeMesh tet = example("tetrahedron.obj");
  const Surface surface(tet, Method::mdc);
  const SceneGeometry scene = build_scene(tet, surface, 4);
  const auto ranges = patch_vertex_ranges(scene.surface);
  // 12 corners, each its own (4 + 1)^2 grid: what the modeler re-uploads per edited patch.
  ASSERT_EQ(ranges.size(), 12u);
  for (const PatchRange& r : ranges) EXPECT_EQ(r.num_vertices, 25);
  EXPECT_EQ(scene.extraordinary.size(), 8u);  // 4 vertices of valence 3, 4 triangles
  EXPECT_FALSE(scene.bounds.empty());
  // The camera focused on an extraordinary point looks at it.
  const Camera camera = focus_camera(scene.extraordinary.front(), scene, 1.0);
  EXPECT_LT((camera.target - scene.extraordinary.front().position).norm(), 1e-12);
  EXPECT_GT((camera.eye - camera.target).dot(scene.extraordinary.front().normal), 0.0);
}

TEST(RenderOptions, ParseSizesPointsAndOverlays) {
  EXPECT_EQ(parse_image_size("640x480").width, 640);
  EXPECT_EQ(parse_image_size("640x480").height, 480);
  for (const char* bad :
       {"", "640", "x480", "640x", "0x10", "-5x5", "10x10x10", "1e3x5", "9000x10"}) {
    EXPECT_THROW(parse_image_size(bad), UsageError) << bad;
  }
  EXPECT_EQ(parse_point("1,-2.5,3e-1", "--eye"), Vec3(1, -2.5, 0.3));
  for (const char* bad : {"", "1,2", "1,2,3,4", "1,,3", "a,b,c", "1,2,inf", "1,2,3,"}) {
    EXPECT_THROW(parse_point(bad, "--eye"), UsageError) << bad;
  }
  RenderStyle style;
  parse_overlays("mesh,ev,tess", style);
  EXPECT_TRUE(style.shows(Overlay::mesh));
  EXPECT_TRUE(style.shows(Overlay::tessellation));
  EXPECT_FALSE(style.shows(Overlay::kgons));
  EXPECT_TRUE(style.markers);
  EXPECT_THROW(parse_overlays("mesh,,ev", style), UsageError);
}

}  // namespace
}  // namespace stitch
