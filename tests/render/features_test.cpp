// Open surfaces and sharp features in pictures: the inside of a box open at the top is shaded
// (its back faces are neither culled nor black), holes make no faces or K-gons, and boundary
// and crease lines stand out in the mesh overlay and with the extraordinary points.
#include <gtest/gtest.h>

#include <algorithm>

#include "stitch/eval/surface.hpp"
#include "stitch/mesh/build.hpp"
#include "stitch/render/gl_context.hpp"
#include "stitch/render/image.hpp"
#include "stitch/render/overlays.hpp"
#include "stitch/render/scene.hpp"
#include "test_helpers.hpp"

namespace stitch {
namespace {

/// The unit cube without its top face (z = +0.5): a box open at the top.
HalfedgeMesh open_box() {
  PolygonSoup s;
  for (int i = 0; i < 8; ++i)
    s.positions.emplace_back((i & 1) ? 0.5 : -0.5, (i & 2) ? 0.5 : -0.5, (i & 4) ? 0.5 : -0.5);
  s.faces = {{0, 2, 3, 1}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  return build_mesh(s);
}

int count_colour(const LineSet& lines, const Colour& c) {
  return static_cast<int>(std::count(lines.colours.begin(), lines.colours.end(), c));
}

TEST(FeatureOverlays, HolesMakeNoFacesAndBoundariesStandOut) {
  const HalfedgeMesh box = open_box();
  ASSERT_EQ(box.num_faces(), 6);  // five faces and the hole
  // input_faces: 5 quads fanned into 4 triangles each; none for the hole.
  EXPECT_EQ(input_faces(box).quads.size(), 5u * 4u);

  const LineSet mesh = mesh_lines(box);
  EXPECT_EQ(mesh.num_segments(), 12);
  EXPECT_EQ(count_colour(mesh, palette::boundary), 4);
  EXPECT_EQ(count_colour(mesh, palette::mesh), 8);
  for (int i = 0; i < mesh.num_segments(); ++i)
    EXPECT_EQ(mesh.width(i), mesh.colours[i] == palette::boundary ? sharp_line_width : 1.0f);

  const Surface surface(box, Method::mdc);
  const KgonSet& kgons = surface.bezier().kgons;
  // K-gons: 5 face 4-gons, 4 bottom vertex 3-gons, 4 rim sectors of two patches (their two
  // points closed through the curve point: 3 segments), 8 smooth edge 4-gons and 4 boundary
  // edge K-gons whose hole side is the midpoint (3 segments).
  const LineSet k = kgon_lines(box, kgons);
  EXPECT_EQ(count_colour(k, palette::face_kgon), 5 * 4);
  EXPECT_EQ(count_colour(k, palette::vertex_kgon), 4 * 3 + 4 * 3);
  EXPECT_EQ(count_colour(k, palette::edge_kgon), 8 * 4 + 4 * 3);

  // Only the bottom corners are extraordinary: the rim sectors close to K = 4.
  const auto points = extraordinary_points(box, kgons);
  ASSERT_EQ(points.size(), 4u);
  for (const ExtraordinaryPoint& p : points) {
    EXPECT_EQ(p.k, 3);
    EXPECT_LT(p.position.z(), 0.0);
  }

  // The sharp curves: 4 boundary edges, two patch sides each, 5 segments per side. The rim's
  // curve only reads rim vertices, so it stays at their height.
  const LineSet curves = sharp_curve_lines(box, surface, 5);
  EXPECT_EQ(curves.num_segments(), 4 * 2 * 5);
  EXPECT_EQ(count_colour(curves, palette::boundary), curves.num_segments());
  for (const Vec3& p : curves.points) EXPECT_NEAR(p.z(), 0.5, 1e-12);
  // A closed mesh has none.
  const HalfedgeMesh closed = [] {
    PolygonSoup s;
    for (int i = 0; i < 8; ++i)
      s.positions.emplace_back((i & 1) ? 0.5 : -0.5, (i & 2) ? 0.5 : -0.5, (i & 4) ? 0.5 : -0.5);
    s.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    return build_mesh(s);
  }();
  EXPECT_EQ(sharp_curve_lines(closed, Surface(closed, Method::mdc), 5).num_segments(), 0);
  EXPECT_TRUE(mesh_lines(closed).widths.empty());
}

class OpenSurfaceRender : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { context_ = std::make_unique<OffscreenContext>(); }
  static void TearDownTestSuite() { context_.reset(); }
  void SetUp() override { context_->make_current(); }

  static std::unique_ptr<OffscreenContext> context_;
};
std::unique_ptr<OffscreenContext> OpenSurfaceRender::context_;

TEST_F(OpenSurfaceRender, InsideOfAnOpenBoxIsShaded) {
  const HalfedgeMesh box = open_box();
  const Surface surface(box, Method::mdc);
  const SceneGeometry scene = build_scene(box, surface, 8);
  Renderer renderer;
  upload_scene(renderer, scene);
  // Straight down into the opening: the middle of the image sees the inside of the bottom,
  // the back side of its patches (they face outward, i.e. down).
  const Camera camera = look_at(Vec3(0.05, 0.1, 3.0), Vec3::Zero(), scene.bounds);
  constexpr int kSize = 96;
  const Image im = render_image(renderer, camera, RenderStyle{}, kSize, kSize);
  int inside = 0;
  for (int y = kSize / 2 - 4; y < kSize / 2 + 4; ++y)
    for (int x = kSize / 2 - 4; x < kSize / 2 + 4; ++x) {
      const std::uint8_t* p = im.pixel(x, y);
      const int brightest = std::max({p[0], p[1], p[2]});
      // Not the white background, and lit (not black): a culled or unlit back face fails.
      EXPECT_LT(brightest, 250) << x << "," << y;
      EXPECT_GT(brightest, 60) << x << "," << y;
      // The back-side tint (more red than green) says these are the patches' back faces.
      inside += p[0] > p[1] + 10 ? 1 : 0;
    }
  EXPECT_EQ(inside, 64);

  // The `ev` overlay draws the boundary curves along with the extraordinary points.
  RenderStyle with_ev;
  with_ev.markers = true;
  ASSERT_GT(scene.sharp_curves.num_segments(), 0);
  const Image with_curves = render_image(renderer, camera, with_ev, kSize, kSize);
  renderer.set_markers(extraordinary_markers(scene.extraordinary));
  const Image without_curves = render_image(renderer, camera, with_ev, kSize, kSize);
  EXPECT_GT(test::mean_difference(with_curves, without_curves), 0.5);
}

}  // namespace
}  // namespace stitch
