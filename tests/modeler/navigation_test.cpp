// Camera navigation and picking, without a window.
#include "stitch/modeler/navigation.hpp"

#include <gtest/gtest.h>

#include "stitch/topology/primitives.hpp"

namespace stitch::modeler {
namespace {

BoundingBox cube_box() {
  BoundingBox b;
  b.extend(Vec3(-1, -1, -1));
  b.extend(Vec3(1, 1, 1));
  return b;
}

TEST(ModelerNavigation, StandardViewsLookFromTheSameSidesAsTheRenderer) {
  // Tolerance 1e-9: the directions come from sines and cosines of exact angles.
  for (View v :
       {View::front, View::back, View::left, View::right, View::top, View::bottom, View::iso}) {
    SCOPED_TRACE(to_string(v));
    OrbitView o;
    o.set_standard(v, cube_box());
    const Camera expected = frame_view(v, cube_box(), 1.0);
    const Vec3 want = (expected.eye - expected.target).normalized();
    EXPECT_LT((o.eye_direction() - want).norm(), 1e-9);
    const Camera c = o.camera(cube_box());
    // The image's up direction: the up vector made perpendicular to the view direction.
    auto image_up = [&](const Vec3& up) { return (up - up.dot(want) * want).normalized(); };
    EXPECT_LT((image_up(c.up) - image_up(expected.up)).norm(), 1e-9);
    // Framed: the box's sphere fits in the field of view.
    EXPECT_GE(o.distance * std::sin(o.fov_y_deg * M_PI / 360.0), cube_box().radius());
    EXPECT_LT(c.near_plane, (c.eye - c.target).norm() - cube_box().radius());
    EXPECT_GT(c.far_plane, (c.eye - c.target).norm() + cube_box().radius());
  }
}

TEST(ModelerNavigation, WithYUpTheOrbitTurnsAboutYAndTheViewsAreTheRenderers) {
  // Tolerance 1e-9 as above.
  for (View v : {View::front, View::top, View::iso}) {
    SCOPED_TRACE(to_string(v));
    OrbitView o;
    o.up = UpAxis::y;
    o.set_standard(v, cube_box());
    const Camera expected = frame_view(v, cube_box(), 1.0, UpAxis::y);
    EXPECT_LT((o.eye_direction() - (expected.eye - expected.target).normalized()).norm(), 1e-9);
  }
  OrbitView o;
  o.up = UpAxis::y;
  o.set_standard(View::front, cube_box());
  EXPECT_LT((o.eye_direction() - Vec3::UnitZ()).norm(), 1e-9);  // front of a y-up model: from +z
  const double height = o.eye_direction().y();
  o.orbit(100, 0);  // a turn about y keeps the eye's height
  EXPECT_NEAR(o.eye_direction().y(), height, 1e-12);
  EXPECT_GT(o.eye_direction().x() * o.eye_direction().x(), 0.1);
}

TEST(ModelerNavigation, OrbitPanZoom) {
  OrbitView o;
  o.set_standard(View::front, cube_box());
  const double d = o.distance;
  o.zoom(1);
  EXPECT_NEAR(o.distance, 0.9 * d, 1e-12);
  o.orbit(0, 1000);  // pitch is clamped at the pole
  EXPECT_EQ(o.pitch_deg, 90.0);
  o.set_standard(View::front, cube_box());
  o.pan(100, 0, 800);  // dragging right moves the model right: the target moves left (-x)
  EXPECT_LT(o.target.x(), 0.0);
  EXPECT_NEAR(o.target.y(), 0.0, 1e-12);
}

TEST(ModelerNavigation, PixelRayThroughTheCentreHitsTheTarget) {
  OrbitView o;
  o.set_standard(View::iso, cube_box());
  const Camera c = o.camera(cube_box());
  const Ray r = pixel_ray(c, 399.5, 299.5, 800, 600);  // pixel centres: +0.5
  const Vec3 to_target = (c.target - c.eye).normalized();
  EXPECT_LT((r.direction - to_target).norm(), 1e-9);
}

TEST(ModelerNavigation, PicksTheNearestFaceAndItsElements) {
  const HalfedgeMesh cube = make_cube();
  // Straight down onto the top face (face 2, z = 1) near vertex 7 = (1, 1, 1).
  const Ray r{Vec3(0.8, 0.7, 5), Vec3(0, 0, -1)};
  const auto f = pick(cube, r, PickKind::face);
  ASSERT_TRUE(f);
  EXPECT_EQ(f->index, 1);
  EXPECT_LT((f->point - Vec3(0.8, 0.7, 1)).norm(), 1e-12);
  EXPECT_EQ(describe(cube, *f), "face 2");
  const auto v = pick(cube, r, PickKind::vertex);
  ASSERT_TRUE(v);
  EXPECT_EQ(describe(cube, *v), "vertex 7");
  const auto k = pick(cube, r, PickKind::corner);
  ASSERT_TRUE(k);
  EXPECT_EQ(describe(cube, *k), "corner 7@2");
  // Nearest side of the top face to (0.8, 0.7): x = 1, the edge 6-7.
  const auto e = pick(cube, r, PickKind::edge);
  ASSERT_TRUE(e);
  EXPECT_EQ(describe(cube, *e), "edge 6 7@2");
  EXPECT_FALSE(pick(cube, Ray{Vec3(5, 5, 5), Vec3(1, 0, 0)}, PickKind::face));
  EXPECT_THROW(parse_pick_kind("loop"), Error);
}

}  // namespace
}  // namespace stitch::modeler
