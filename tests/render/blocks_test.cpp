// A surface drawn block by block (SceneSurface::blocks, surface_blocks: what `stitch render` and
// `stitch compare` draw, in memory that does not grow with the mesh and resolution) gives the
// picture of one upload of the whole tessellation. The same triangles and lines reach the GPU in
// the same order, only in several draw calls, and the depth buffer resolves them as in one: so
// the images are compared for equality, pixel for pixel, in every mode and with every overlay.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "stitch/eval/uv_surface.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/render/gl_context.hpp"
#include "stitch/render/image.hpp"
#include "stitch/render/scene.hpp"
#include "test_helpers.hpp"

namespace stitch {
namespace {

constexpr int kSize = 96;
constexpr int kResolution = 6;

class SurfaceBlocksTest : public ::testing::TestWithParam<std::string> {
 protected:
  static void SetUpTestSuite() { context_ = std::make_unique<OffscreenContext>(); }
  static void TearDownTestSuite() { context_.reset(); }
  void SetUp() override {
    context_->make_current();
    mesh_ = read_mesh(std::string(STITCH_EXAMPLES_DIR) + "/" + GetParam(), {}, &report_);
    surface_ = std::make_unique<Surface>(mesh_, Method::mdc);
    whole_ = build_scene(mesh_, *surface_, kResolution);
    renderer_ = std::make_unique<Renderer>();
  }
  void TearDown() override { renderer_.reset(); }

  Image render(const SceneGeometry& scene, const RenderStyle& style,
               const SurfaceBlocks* blocks = nullptr) {
    upload_scene(*renderer_, scene);
    const Camera camera = frame_view(View::iso, scene.bounds, 1.0);
    return render_image(*renderer_, camera, style, kSize, kSize, {}, blocks);
  }

  static std::unique_ptr<OffscreenContext> context_;
  HalfedgeMesh mesh_;
  BuildReport report_;
  std::unique_ptr<Surface> surface_;
  SceneGeometry whole_;
  std::unique_ptr<Renderer> renderer_;
};
std::unique_ptr<OffscreenContext> SurfaceBlocksTest::context_;

TEST_P(SurfaceBlocksTest, BlocksDrawWhatOneUploadDraws) {
  const SceneGeometry outline =
      build_scene(mesh_, *surface_, kResolution, all_overlays, SceneSurface::blocks);
  EXPECT_TRUE(outline.surface.positions.empty());
  EXPECT_TRUE(outline.overlays[static_cast<int>(Overlay::tessellation)].points.empty());
  // The bounds, hence the camera, are the whole tessellation's.
  EXPECT_EQ(outline.bounds.min, whole_.bounds.min);
  EXPECT_EQ(outline.bounds.max, whole_.bounds.max);

  const int patches = static_cast<int>(surface_->corners().size());
  for (const char* mode : {"shaded", "zebra", "isophote", "levels", "patches"}) {
    RenderStyle style;
    style.mode = parse_shading_mode(mode);
    style.overlays = all_overlays;
    style.markers = true;
    const Image expected = render(whole_, style);
    // One patch a block, a size that leaves a last block short, and one block of all.
    for (const int per_block : {1, 5, patches}) {
      const SurfaceBlocks blocks =
          surface_blocks(mesh_, *surface_, kResolution, nullptr, per_block);
      EXPECT_EQ(test::mean_difference(expected, render(outline, style, &blocks)), 0.0)
          << mode << ", " << per_block << " patches a block";
    }
  }
}

TEST_P(SurfaceBlocksTest, UnshadedBlocksGiveTheTessellationOverlayOnly) {
  // --draw input: the input polygons are shaded, the blocks give the tessellation's lines.
  SceneGeometry outline =
      build_scene(mesh_, *surface_, kResolution, all_overlays, SceneSurface::blocks);
  EXPECT_TRUE(outline.input.positions.empty());
  outline.input = input_faces(mesh_);
  RenderStyle style;
  style.show(Overlay::tessellation);
  const auto input_picture = [&](const SceneGeometry& scene, const SurfaceBlocks* blocks) {
    upload_scene(*renderer_, scene, true);
    return render_image(*renderer_, frame_view(View::iso, scene.bounds, 1.0), style, kSize, kSize,
                        {}, blocks);
  };
  SurfaceBlocks blocks = surface_blocks(mesh_, *surface_, kResolution, nullptr, 3);
  blocks.shaded = false;
  const Image expected = input_picture(whole_, nullptr);
  EXPECT_EQ(test::mean_difference(expected, input_picture(outline, &blocks)), 0.0);
  // ... and the lines are there: without them the picture differs.
  style.show(Overlay::tessellation, false);
  EXPECT_GT(test::mean_difference(expected, input_picture(outline, &blocks)), 0.1);
}

INSTANTIATE_TEST_SUITE_P(Examples, SurfaceBlocksTest,
                         ::testing::Values("cube_uv.obj", "cube_creased.obj", "open_box.obj"));

TEST(SurfaceBlocksChecker, TextureCoordinatesFollowTheBlocks) {
  const OffscreenContext context;
  BuildReport report;
  const HalfedgeMesh mesh =
      read_mesh(std::string(STITCH_EXAMPLES_DIR) + "/cube_uv.obj", {}, &report);
  const Surface surface(mesh, Method::mdc);
  const UvSurface uvs(mesh, report.corner_uvs);
  SceneGeometry whole = build_scene(mesh, surface, kResolution, OverlaySelection{});
  add_texcoords(whole, mesh, report.corner_uvs, uvs);
  const SceneGeometry outline =
      build_scene(mesh, surface, kResolution, OverlaySelection{}, SceneSurface::blocks);
  RenderStyle style;
  style.mode = ShadingMode::checker;
  const Camera camera = frame_view(View::iso, whole.bounds, 1.0);
  Renderer renderer;
  upload_scene(renderer, whole);
  const Image expected = render_image(renderer, camera, style, kSize, kSize);
  upload_scene(renderer, outline);
  const SurfaceBlocks blocks = surface_blocks(mesh, surface, kResolution, &uvs, 7);
  EXPECT_EQ(test::mean_difference(expected,
                                  render_image(renderer, camera, style, kSize, kSize, {}, &blocks)),
            0.0);
  // Without texture coordinates the blocks are shaded plainly: a different picture.
  const SurfaceBlocks plain = surface_blocks(mesh, surface, kResolution, nullptr, 7);
  EXPECT_GT(test::mean_difference(expected,
                                  render_image(renderer, camera, style, kSize, kSize, {}, &plain)),
            1.0);
}

}  // namespace
}  // namespace stitch
