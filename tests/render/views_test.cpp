// The named views follow the one up-axis convention of stitch: z is up (the cube's faces 1 and
// 2 are its bottom z = -1 and top z = 1, face 3 its front y = -1).
#include <gtest/gtest.h>
#include <stb_image.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "../temp_folder.hpp"
#include "cli_helpers.hpp"
#include "stitch/render/camera.hpp"
#include "test_helpers.hpp"

namespace stitch {
namespace {

using stitch::testing::read_file;
using stitch::testing::TempFolder;
using test::load_png;
using test::run_stitch;

struct Expected {
  View view;
  Vec3 from, right, up;  ///< towards the eye; the world directions shown right and up
};

const Expected kViews[] = {
    {View::front, -Vec3::UnitY(), Vec3::UnitX(), Vec3::UnitZ()},
    {View::back, Vec3::UnitY(), -Vec3::UnitX(), Vec3::UnitZ()},
    {View::left, -Vec3::UnitX(), -Vec3::UnitY(), Vec3::UnitZ()},
    {View::right, Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()},
    {View::top, Vec3::UnitZ(), Vec3::UnitX(), Vec3::UnitY()},
    {View::bottom, -Vec3::UnitZ(), -Vec3::UnitX(), Vec3::UnitY()},
};

TEST(Views, ZIsUpAndEachViewFacesItsSideOfTheCube) {
  BoundingBox box;
  box.extend(Vec3(-1, -1, -1));
  box.extend(Vec3(1, 1, 1));
  for (const Expected& e : kViews) {
    SCOPED_TRACE(to_string(e.view));
    const Camera c = frame_view(e.view, box, 1.0);
    EXPECT_LT(((c.eye - c.target).normalized() - e.from).norm(), 1e-12);
    // Where the image shows world points: right of the centre along `right`, above along `up`.
    const Eigen::Matrix4f m = projection_matrix(c, 1.0) * view_matrix(c);
    auto ndc = [&](const Vec3& p) {
      const Eigen::Vector4f q = m * Eigen::Vector4f(p.x(), p.y(), p.z(), 1.0f);
      return Eigen::Vector2f(q.x() / q.w(), q.y() / q.w());
    };
    EXPECT_GT(ndc(0.5 * e.right).x(), 0.1f);
    EXPECT_NEAR(ndc(0.5 * e.right).y(), 0.0f, 1e-6f);
    EXPECT_GT(ndc(0.5 * e.up).y(), 0.1f);
    EXPECT_NEAR(ndc(0.5 * e.up).x(), 0.0f, 1e-6f);
    EXPECT_EQ(view_direction(e.view).from, e.from);
  }
  // iso: from (1, 1, 1), z up in the image.
  const ViewDirection iso = view_direction(View::iso);
  EXPECT_LT((iso.from - Vec3(1, 1, 1).normalized()).norm(), 1e-15);
  EXPECT_NEAR(iso.up.dot(iso.from), 0.0, 1e-15);
  EXPECT_GT(iso.up.z(), 0.8);
}

// Explicit eyes (--eye) and close-ups (--focus-ev) keep the same convention: world +z shows
// straight up in the image, except looking straight down or up z, where +y does (as in top).
TEST(Views, ExplicitEyesAndCloseUpsKeepZUp) {
  BoundingBox box;
  box.extend(Vec3(-1, -1, -1));
  box.extend(Vec3(1, 1, 1));
  struct Case {
    Camera camera;
    Vec3 up;  ///< the world direction the image must show straight up
  };
  const Case cases[] = {
      {look_at(Vec3(3, -4, 5), Vec3::Zero(), box), Vec3::UnitZ()},
      {look_at(Vec3(2.5, -4, -3), Vec3::Zero(), box), Vec3::UnitZ()},
      {look_at(Vec3(-6, 0.5, 0.2), Vec3::Zero(), box), Vec3::UnitZ()},
      {look_at(Vec3(0, 0, 5), Vec3::Zero(), box), Vec3::UnitY()},
      {look_at(Vec3(0, 0, -5), Vec3::Zero(), box), Vec3::UnitY()},
      {frame_sphere(Vec3::Zero(), 0.5, Vec3(1, 1, 1), 1.0, box), Vec3::UnitZ()},
      {frame_sphere(Vec3::Zero(), 0.5, -Vec3::UnitX(), 1.0, box), Vec3::UnitZ()},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(::testing::Message() << "eye " << c.camera.eye.transpose());
    const Eigen::Matrix4f m = projection_matrix(c.camera, 1.0) * view_matrix(c.camera);
    auto ndc = [&](const Vec3& p) {
      const Eigen::Vector4f q = m * Eigen::Vector4f(p.x(), p.y(), p.z(), 1.0f);
      return Eigen::Vector2f(q.x() / q.w(), q.y() / q.w());
    };
    // The target projects to the centre; a point above it (in world `up`) straight above the
    // centre, up to float round-off of the projection.
    const Eigen::Vector2f centre = ndc(c.camera.target);
    const Eigen::Vector2f above = ndc(c.camera.target + 0.1 * c.up);
    EXPECT_GT(above.y() - centre.y(), 0.01f);
    EXPECT_NEAR(above.x(), centre.x(), 1e-5f);
  }
}

// --up y: every camera is the z-up one turned by from_z_up, (x, y, z) -> (x, z, -y), so a y-up
// model (the z-up one turned the same way) is seen as the z-up one is. The turn permutes
// coordinates and flips a sign, so the comparison is exact.
TEST(Views, YUpCamerasAreTheZUpOnesTurned) {
  BoundingBox box, turned;
  box.extend(Vec3(-1, -2, -3));
  box.extend(Vec3(4, 5, 6));
  turned.extend(from_z_up(box.min, UpAxis::y));
  turned.extend(from_z_up(box.max, UpAxis::y));
  EXPECT_EQ(from_z_up(Vec3::UnitZ(), UpAxis::y), Vec3::UnitY());
  EXPECT_EQ(to_z_up(from_z_up(Vec3(1, 2, 3), UpAxis::y), UpAxis::y), Vec3(1, 2, 3));
  const auto expect_turned = [](const Camera& y_up, const Camera& z_up) {
    EXPECT_EQ(y_up.eye, from_z_up(z_up.eye, UpAxis::y));
    EXPECT_EQ(y_up.target, from_z_up(z_up.target, UpAxis::y));
    EXPECT_EQ(y_up.up, from_z_up(z_up.up, UpAxis::y));
    EXPECT_EQ(y_up.near_plane, z_up.near_plane);
    EXPECT_EQ(y_up.far_plane, z_up.far_plane);
  };
  for (int v = 0; v <= static_cast<int>(View::iso); ++v) {
    const auto view = static_cast<View>(v);
    SCOPED_TRACE(to_string(view));
    expect_turned(frame_view(view, turned, 1.5, UpAxis::y), frame_view(view, box, 1.5));
  }
  for (const Vec3& eye : {Vec3(3, -4, 5), Vec3(0, 0, 9), Vec3(-6, 0.5, 0.2)}) {
    SCOPED_TRACE(::testing::Message() << "eye " << eye.transpose());
    expect_turned(look_at(from_z_up(eye, UpAxis::y), Vec3::Zero(), turned, UpAxis::y),
                  look_at(eye, Vec3::Zero(), box));
    expect_turned(
        frame_sphere(Vec3::Zero(), 0.5, from_z_up(eye, UpAxis::y), 1.0, turned, UpAxis::y),
        frame_sphere(Vec3::Zero(), 0.5, eye, 1.0, box));
  }
}

/// The centre of the drawn pixels relative to the image's centre, image y pointing up; in
/// pixels.
Eigen::Vector2d drawn_centre(const std::string& path) {
  int w = 0, h = 0, channels = 0;
  unsigned char* pixels = stbi_load(path.c_str(), &w, &h, &channels, 4);
  if (pixels == nullptr) return Eigen::Vector2d::Constant(1e9);
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  int count = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const unsigned char* p = pixels + 4 * (static_cast<size_t>(y) * w + x);
      if (p[0] < 240 || p[1] < 240 || p[2] < 240) {
        sum += Eigen::Vector2d(x + 0.5 - w / 2.0, h / 2.0 - (y + 0.5));
        ++count;
      }
    }
  stbi_image_free(pixels);
  return count > 0 ? Eigen::Vector2d(sum / count) : Eigen::Vector2d::Constant(1e9);
}

TEST(Views, RenderedCubeWithTowersShowsEachTowerWhereTheViewPutsIt) {
  // Thin towers on the top (+z, the longest), the right side (+x) and the back (+y): the heavy
  // cube lies opposite the towers that stick out sideways in the image, so the drawn pixels'
  // centre tells which way each axis points.
  TempFolder folder;
  const std::string cube = folder.file("cube.obj"), towers = folder.file("towers.obj");
  ASSERT_EQ(run_stitch(folder, "primitive cube -o '" + cube + "'"), 0);
  ASSERT_EQ(run_stitch(folder, "edit '" + cube +
                                   "' --op 'extrude-face 2 2 0.4' --op 'extrude-face 4 1.5 0.4' "
                                   "--op 'extrude-face 5 1.5 0.4' -o '" +
                                   towers + "'"),
            0)
      << read_file(folder.file("stderr.txt"));
  for (const Expected& e : kViews) {
    SCOPED_TRACE(to_string(e.view));
    const std::string png = folder.file(to_string(e.view) + ".png");
    ASSERT_EQ(run_stitch(folder, "render '" + towers + "' -o '" + png + "' --view " +
                                     to_string(e.view) + " --draw input --size 160x160"),
              0)
        << read_file(folder.file("stderr.txt"));
    const Eigen::Vector2d c = drawn_centre(png);
    // The bounding box is centred, and the towers are thin: the cube's pixels lie on the side
    // the towers do not point to, in each image direction.
    const Vec3 towers_direction(1, 1, 1);
    const double right = towers_direction.dot(e.right), up = towers_direction.dot(e.up);
    EXPECT_GT(-right * c.x(), 3.0) << c.transpose();
    EXPECT_GT(-up * c.y(), 3.0) << c.transpose();
  }
  // The same model turned to y up, as a DCC tool exports it ((x, y, z) -> (x, z, -y)), and
  // rendered with --up y: each view shows it as the z-up one, up to a pixel of rasterization.
  const std::string turned = folder.file("towers-y-up.obj");
  {
    std::istringstream in(read_file(towers));
    std::ostringstream out;
    for (std::string line; std::getline(in, line);) {
      double x = 0, y = 0, z = 0;
      if (line.rfind("v ", 0) == 0 && std::sscanf(line.c_str(), "v %lf %lf %lf", &x, &y, &z) == 3)
        out << "v " << x << ' ' << z << ' ' << -y << '\n';
      else
        out << line << '\n';
    }
    std::ofstream(turned) << out.str();
  }
  for (const Expected& e : kViews) {
    SCOPED_TRACE(to_string(e.view));
    const std::string z_up = folder.file(to_string(e.view) + ".png");
    const std::string y_up = folder.file(to_string(e.view) + "-y-up.png");
    ASSERT_EQ(run_stitch(folder, "render '" + turned + "' -o '" + y_up + "' --view " +
                                     to_string(e.view) + " --up y --draw input --size 160x160"),
              0)
        << read_file(folder.file("stderr.txt"));
    EXPECT_LT((drawn_centre(y_up) - drawn_centre(z_up)).norm(), 1.0);
  }
  EXPECT_NE(run_stitch(folder, "render '" + turned + "' -o x.png --up x"), 0);
}

}  // namespace
}  // namespace stitch
