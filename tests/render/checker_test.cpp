// The checker mode: texture coordinates on the smooth surface drawn as a checkerboard, through
// the library (examples/cube_uv.obj) and through `stitch render --mode checker`.
#include <gtest/gtest.h>
#include <stb_image.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "../temp_folder.hpp"
#include "cli_helpers.hpp"
#include "stitch/eval/uv_surface.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/render/gl_context.hpp"
#include "stitch/render/image.hpp"
#include "stitch/render/scene.hpp"
#include "test_helpers.hpp"

namespace stitch {
namespace {

using stitch::testing::read_file;
using stitch::testing::TempFolder;
using test::load_png;
using test::run_stitch;

const std::string kCubeUv = std::string(STITCH_EXAMPLES_DIR) + "/cube_uv.obj";
const std::string kCube = std::string(STITCH_EXAMPLES_DIR) + "/cube.obj";
constexpr int kSize = 128;

bool is_surface(const std::uint8_t* p) {
  return std::abs(int(p[0]) - 255) + std::abs(int(p[1]) - 255) + std::abs(int(p[2]) - 255) > 24;
}
// The default checker colour is orange, the surface colour a bluish grey: red minus blue
// tells them apart in light and shadow alike (shading scales both, specular adds to both).
bool is_checker_colour(const std::uint8_t* p) {
  return is_surface(p) && int(p[0]) - p[2] > 30;
}
bool is_base_colour(const std::uint8_t* p) {
  return is_surface(p) && int(p[2]) >= p[0];
}

int count(const Image& im, bool (*test)(const std::uint8_t*)) {
  int n = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) n += test(im.pixel(x, y)) ? 1 : 0;
  return n;
}

// Horizontal neighbours inside the surface's silhouette (2 pixels away from the background,
// whose antialiased edge would count too) whose colours differ by more than 60 (of 765, summed
// over the channels): every row crossing a checker edge has one, smooth shading changes by a
// few units per pixel.
int sharp_steps(const Image& im) {
  const auto inside = [&](int x, int y) {
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx) {
        const int u = x + dx, v = y + dy;
        if (u < 0 || v < 0 || u >= im.width || v >= im.height || !is_surface(im.pixel(u, v)))
          return false;
      }
    return true;
  };
  int steps = 0;
  for (int y = 0; y < im.height; ++y) {
    for (int x = 0; x + 1 < im.width; ++x) {
      if (!inside(x, y) || !inside(x + 1, y)) continue;
      const std::uint8_t *a = im.pixel(x, y), *b = im.pixel(x + 1, y);
      int step = 0;
      for (int c = 0; c < 3; ++c) step += std::abs(int(a[c]) - int(b[c]));
      steps += step > 60 ? 1 : 0;
    }
  }
  return steps;
}

class CheckerTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { context_ = std::make_unique<OffscreenContext>(); }
  static void TearDownTestSuite() { context_.reset(); }
  void SetUp() override {
    context_->make_current();
    mesh_ = read_mesh(kCubeUv, {}, &report_);
    ASSERT_FALSE(report_.corner_uvs.empty());
    surface_ = std::make_unique<Surface>(mesh_, Method::mdc);
    scene_ = build_scene(mesh_, *surface_, 12);
    camera_ = frame_view(View::iso, scene_.bounds, 1.0);
    renderer_ = std::make_unique<Renderer>();
  }
  void TearDown() override { renderer_.reset(); }

  Image render(ShadingMode mode) {
    RenderStyle style;
    style.mode = mode;
    return render_image(*renderer_, camera_, style, kSize, kSize);
  }

  static std::unique_ptr<OffscreenContext> context_;
  HalfedgeMesh mesh_;
  BuildReport report_;
  std::unique_ptr<Surface> surface_;
  SceneGeometry scene_;
  Camera camera_;
  std::unique_ptr<Renderer> renderer_;
};
std::unique_ptr<OffscreenContext> CheckerTest::context_;

TEST_F(CheckerTest, TexcoordsAtPatchCornersAreTheInputsUvs) {
  // Bilinear UVs reproduce the corner's own UV exactly at (u, v) = (0, 0) of its patch.
  const UvSurface uvs(mesh_, report_.corner_uvs, UvMode::linear);
  const std::vector<Eigen::Vector2d> st = surface_texcoords(scene_.surface, uvs);
  ASSERT_EQ(st.size(), scene_.surface.positions.size());
  int corners = 0;
  for (size_t i = 0; i < st.size(); ++i) {
    if (scene_.surface.uv[i] != Eigen::Vector2d::Zero()) continue;
    const int h = scene_.surface.patch[i];
    EXPECT_LT((st[i] - report_.corner_uvs.uv[report_.corner_uvs.index[h]]).norm(), 1e-12) << i;
    ++corners;
  }
  EXPECT_EQ(corners, 24);  // one per patch: 6 quads x 4 corners

  const std::vector<Eigen::Vector2d> input = input_face_texcoords(mesh_, report_.corner_uvs);
  ASSERT_EQ(input.size(), scene_.input.positions.size());
  // The first face's fan: its centre, then its four corners (bottom: vt 13 14 3 2).
  EXPECT_LT((input[0] - Eigen::Vector2d(0.375, 0.25)).norm(), 1e-12);
  EXPECT_LT((input[1] - Eigen::Vector2d(0.25, 0.125)).norm(), 1e-12);
}

TEST_F(CheckerTest, CheckerShowsBothColoursAndShadedHasNoPattern) {
  const UvSurface uvs(mesh_, report_.corner_uvs);
  add_texcoords(scene_, mesh_, report_.corner_uvs, uvs);
  upload_scene(*renderer_, scene_);
  const Image checker = render(ShadingMode::checker);
  const Image shaded = render(ShadingMode::shaded);

  const int on_surface = count(checker, is_surface);
  EXPECT_GT(on_surface, kSize * kSize / 6);  // the cube fills a quarter of the frame
  // Each visible face shows 2 x 2 squares: both colours cover a good share of the cube.
  EXPECT_GT(count(checker, is_checker_colour), on_surface / 4);
  EXPECT_GT(count(checker, is_base_colour), on_surface / 4);

  EXPECT_NEAR(count(shaded, is_surface), on_surface, on_surface / 50);
  EXPECT_EQ(count(shaded, is_checker_colour), 0);
  // The checker's edges cross the cube's rows several times each; shading has no such step.
  const int checker_steps = sharp_steps(checker), shaded_steps = sharp_steps(shaded);
  EXPECT_GT(checker_steps, 150);
  EXPECT_LT(shaded_steps, checker_steps / 20) << "checker " << checker_steps;

  // The texture coordinates live beside the vertices: shaded is the same picture without them.
  renderer_->set_surface(scene_.surface);
  EXPECT_EQ(test::mean_difference(render(ShadingMode::shaded), shaded), 0.0);
}

TEST_F(CheckerTest, TexcoordsMustMatchTheSurfaceAndGoWithIt) {
  const UvSurface uvs(mesh_, report_.corner_uvs);
  add_texcoords(scene_, mesh_, report_.corner_uvs, uvs);
  renderer_->set_surface(scene_.surface);
  EXPECT_THROW(renderer_->set_surface_texcoords(scene_.input_texcoords), std::invalid_argument);
  renderer_->set_surface_texcoords(scene_.surface_texcoords);
  EXPECT_GT(count(render(ShadingMode::checker), is_checker_colour), 0);
  // A new surface drops them, and a surface without them is drawn as in shaded.
  renderer_->set_surface(scene_.surface);
  EXPECT_EQ(test::mean_difference(render(ShadingMode::checker), render(ShadingMode::shaded)), 0.0);
}

TEST(CliChecker, RefusesAMeshWithoutTextureCoordinates) {
  TempFolder folder;
  const std::string out = folder.file("cube.png");
  EXPECT_EQ(run_stitch(folder, "render '" + kCube + "' -o '" + out + "' --mode checker"), 2);
  EXPECT_NE(read_file(folder.file("stderr.txt"))
                .find("--mode checker needs texture coordinates: " + kCube + " has none"),
            std::string::npos)
      << read_file(folder.file("stderr.txt"));
  EXPECT_FALSE(std::filesystem::exists(out));
  // --uv only means something to the checker.
  EXPECT_EQ(run_stitch(folder, "render '" + kCubeUv + "' -o '" + out + "' --uv linear"), 2);
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(CliChecker, RendersTheCheckerSmoothAndLinear) {
  TempFolder folder;
  std::vector<Image> images;
  for (const std::string options : {"", " --uv linear", " --checks 2"}) {
    const std::string out = folder.file("im.png");
    ASSERT_EQ(run_stitch(folder, "render '" + kCubeUv + "' -o '" + out +
                                     "' --size 96x96 --mode checker" + options),
              0)
        << options << ": " << read_file(folder.file("stderr.txt"));
    images.push_back(load_png(out));
    ASSERT_EQ(images.back().width, 96);
    EXPECT_GT(count(images.back(), is_checker_colour), 96 * 96 / 20) << options;
    EXPECT_GT(count(images.back(), is_base_colour), 96 * 96 / 20) << options;
  }
  // Identical inputs give identical images; smooth and linear UVs differ near the corners
  // (0.6 of 255 at this size), 8 and 2 squares a side everywhere.
  EXPECT_GT(test::mean_difference(images[0], images[1]), 0.2);
  EXPECT_GT(test::mean_difference(images[0], images[2]), 2.0);
}

}  // namespace
}  // namespace stitch
