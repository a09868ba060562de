// The renderer on a hand-made sphere: headless context, image size, modes, overlays, partial
// vertex updates, cameras and PNG encoding. Images are 96x96 to keep the tests fast.
#include "stitch/render/renderer.hpp"

#include <gtest/gtest.h>
#include <stb_image.h>

#include <Eigen/Geometry>

#include "stitch/render/gl_context.hpp"
#include "stitch/render/image.hpp"
#include "test_helpers.hpp"

namespace stitch {
namespace {

constexpr int kSize = 96;

class RendererTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { context_ = std::make_unique<OffscreenContext>(); }
  static void TearDownTestSuite() { context_.reset(); }
  void SetUp() override {
    context_->make_current();
    renderer_ = std::make_unique<Renderer>();
    sphere_ = test::cube_sphere(8);
    renderer_->set_surface(sphere_);
    // The sphere's silhouette fills the smaller image side.
    camera_ = frame_sphere(Vec3::Zero(), 1.0, Vec3(1, 1, 1), 1.0, bounding_box(sphere_.positions));
  }
  void TearDown() override { renderer_.reset(); }

  Image render(const RenderStyle& style, int w = kSize, int h = kSize) {
    return render_image(*renderer_, camera_, style, w, h);
  }

  static std::unique_ptr<OffscreenContext> context_;
  std::unique_ptr<Renderer> renderer_;
  TessellatedMesh sphere_;
  Camera camera_;
};
std::unique_ptr<OffscreenContext> RendererTest::context_;

TEST_F(RendererTest, ContextIsOpenGL33OrLater) {
  const std::string description = context_->description();
  EXPECT_NE(description.find("OpenGL"), std::string::npos) << description;
}

TEST_F(RendererTest, ImageHasRequestedSizeAndIsNotBlank) {
  camera_ =
      frame_sphere(Vec3::Zero(), 1.0, Vec3(1, 1, 1), 96.0 / 64.0, bounding_box(sphere_.positions));
  const Image im = render({}, 96, 64);
  EXPECT_EQ(im.width, 96);
  EXPECT_EQ(im.height, 64);
  ASSERT_EQ(im.rgba.size(), 96u * 64u * 4u);
  // The sphere is a disc of diameter ~ the image height: about half of the pixels.
  EXPECT_GT(test::count_non_background(im), 96 * 64 / 4);
  // ... and does not cover the corners.
  EXPECT_EQ(im.pixel(0, 0)[0], 255);
  EXPECT_EQ(im.pixel(95, 63)[1], 255);
}

TEST_F(RendererTest, EveryModeDiffersFromEveryOther) {
  std::vector<Image> images;
  for (const auto* name : {"shaded", "zebra", "isophote", "levels", "patches"}) {
    RenderStyle style;
    style.mode = parse_shading_mode(name);
    images.push_back(render(style));
    EXPECT_GT(test::count_non_background(images.back()), kSize * kSize / 4) << name;
  }
  for (size_t i = 0; i < images.size(); ++i) {
    for (size_t j = i + 1; j < images.size(); ++j) {
      // 2 of 255 on average: far above the round-off of one renderer, far below any real change.
      EXPECT_GT(test::mean_difference(images[i], images[j]), 2.0) << i << " vs " << j;
    }
  }
}

TEST_F(RendererTest, ZebraHasBlackAndWhiteStripes) {
  RenderStyle style;
  style.mode = ShadingMode::zebra;
  const Image im = render(style);
  int dark = 0;
  for (int y = 0; y < im.height; ++y) {
    for (int x = 0; x < im.width; ++x) dark += im.pixel(x, y)[0] < 40;
  }
  // Black stripes cover a good share of the sphere but not all of it (white ones between).
  const int covered = test::count_non_background(im);
  EXPECT_GT(dark, covered / 5);
  EXPECT_LT(dark, covered * 4 / 5);
}

TEST_F(RendererTest, OverlaysAndMarkersAreDrawn) {
  RenderStyle plain;
  const Image without = render(plain);
  LineSet lines;
  lines.add(Vec3(-1.2, -1.2, 1.2), Vec3(1.2, 1.2, 1.2), palette::face_kgon);
  renderer_->set_overlay(Overlay::kgons, lines);
  MarkerSet markers;
  markers.positions.push_back(Vec3(1, 1, 1).normalized());
  markers.colours.push_back(palette::extraordinary);
  renderer_->set_markers(markers);
  RenderStyle with_lines = plain;
  with_lines.show(Overlay::kgons);
  EXPECT_GT(test::mean_difference(without, render(with_lines)), 0.05);
  RenderStyle with_markers = plain;
  with_markers.markers = true;
  EXPECT_GT(test::mean_difference(without, render(with_markers)), 0.05);
  // A shown overlay with nothing uploaded draws nothing.
  RenderStyle empty_overlay = plain;
  empty_overlay.show(Overlay::nets);
  EXPECT_EQ(test::mean_difference(without, render(empty_overlay)), 0.0);
}

TEST_F(RendererTest, UpdatingOnePatchChangesOnlyThatPatch) {
  const auto ranges = patch_vertex_ranges(sphere_);
  ASSERT_EQ(ranges.size(), 6u);
  for (const PatchRange& r : ranges) EXPECT_EQ(r.num_vertices, 81);
  RenderStyle style;
  style.mode = ShadingMode::patches;
  const Image before = render(style);
  // Push the +x patch (patch 0, seen in the iso view) outwards.
  TessellatedMesh moved = sphere_;
  for (int i = ranges[0].first_vertex; i < ranges[0].first_vertex + ranges[0].num_vertices; ++i) {
    moved.positions[i] *= 1.3;
  }
  renderer_->update_surface_vertices(moved, ranges[0].first_vertex, ranges[0].num_vertices);
  const Image after = render(style);
  EXPECT_GT(test::mean_difference(before, after), 0.5);
  // Restoring the block restores the image exactly.
  renderer_->update_surface_vertices(sphere_, ranges[0].first_vertex, ranges[0].num_vertices);
  EXPECT_EQ(test::mean_difference(before, render(style)), 0.0);
  EXPECT_THROW(renderer_->update_surface_vertices(sphere_, 480, 10), std::out_of_range);
}

// The modeler's block surface: updating some blocks (and adding or dropping blocks at the end)
// must draw exactly what uploading the whole result draws. The same triangles in the same
// order give the same pixels, so images are compared for equality.
TEST_F(RendererTest, BlockUpdatesDrawWhatAFullUploadDraws) {
  constexpr int kBlockVertices = 81, kBlockQuads = 64;  // cube_sphere(8): 6 patches of 8x8
  ASSERT_EQ(sphere_.quads.size(), 6u * kBlockQuads);
  RenderStyle style;
  style.mode = ShadingMode::patches;
  auto full_upload_image = [&](const TessellatedMesh& s) {
    renderer_->set_surface(s);
    const Image im = render(style);
    renderer_->set_block_surface(sphere_, kBlockVertices, kBlockQuads);
    return im;
  };
  renderer_->set_block_surface(sphere_, kBlockVertices, kBlockQuads);
  const Image whole = render(style);
  EXPECT_EQ(test::mean_difference(whole, full_upload_image(sphere_)), 0.0);

  // Block 0 pushed out, block 2 emptied (degenerate quads, as for a deleted corner), the last
  // block dropped.
  TessellatedMesh edited = sphere_;
  for (int i = 0; i < kBlockVertices; ++i) edited.positions[i] *= 1.3;
  for (int q = 2 * kBlockQuads; q < 3 * kBlockQuads; ++q) {
    const int base = 2 * kBlockVertices;
    edited.quads[q] = {base, base, base, base};
  }
  const auto drop_last = [&](TessellatedMesh& s) {
    s.positions.resize(5 * kBlockVertices);
    s.normals.resize(5 * kBlockVertices);
    s.uv.resize(5 * kBlockVertices);
    s.patch.resize(5 * kBlockVertices);
    s.level.resize(5 * kBlockVertices);
    s.quads.resize(5 * kBlockQuads);
  };
  drop_last(edited);
  const Image expected = full_upload_image(edited);
  EXPECT_GT(test::mean_difference(whole, expected), 0.5);
  renderer_->set_block_surface(sphere_, kBlockVertices, kBlockQuads);
  renderer_->update_surface_blocks(edited, {0, 2});
  EXPECT_EQ(test::mean_difference(expected, render(style)), 0.0);
  // Back: blocks 0 and 2 listed, block 5 comes back as a new block at the end.
  renderer_->update_surface_blocks(sphere_, {2, 0});
  EXPECT_EQ(test::mean_difference(whole, render(style)), 0.0);

  // Growing past the room kept (6 + 3 + 16 blocks) uploads everything again.
  TessellatedMesh big = sphere_;
  for (int copy = 0; copy < 4; ++copy) {
    const int offset = big.num_vertices();
    for (int i = 0; i < sphere_.num_vertices(); ++i) {
      big.positions.push_back(sphere_.positions[i] * (0.5 + 0.1 * copy));
      big.normals.push_back(sphere_.normals[i]);
      big.uv.push_back(sphere_.uv[i]);
      big.patch.push_back(sphere_.patch[i] + 6 * (copy + 1));
      big.level.push_back(sphere_.level[i]);
    }
    for (auto q : sphere_.quads) {
      for (int& i : q) i += offset;
      big.quads.push_back(q);
    }
  }
  const Image big_image = full_upload_image(big);
  renderer_->update_surface_blocks(big, {});
  EXPECT_EQ(test::mean_difference(big_image, render(style)), 0.0);

  EXPECT_THROW(renderer_->update_surface_blocks(big, {99}), std::out_of_range);
  EXPECT_THROW(renderer_->set_block_surface(sphere_, 80, kBlockQuads), std::invalid_argument);
  renderer_->set_surface(sphere_);
  EXPECT_THROW(renderer_->update_surface_blocks(sphere_, {0}), std::logic_error);
}

TEST_F(RendererTest, PngRoundTrips) {
  const Image im = render({}, 40, 30);
  const auto png = encode_png(im);
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png[1], 'P');
  int w = 0, h = 0, channels = 0;
  unsigned char* pixels =
      stbi_load_from_memory(png.data(), static_cast<int>(png.size()), &w, &h, &channels, 4);
  ASSERT_NE(pixels, nullptr);
  EXPECT_EQ(w, 40);
  EXPECT_EQ(h, 30);
  EXPECT_EQ(std::vector<std::uint8_t>(pixels, pixels + w * h * 4), im.rgba);
  stbi_image_free(pixels);
}

TEST(Camera, NamedViewsKeepTheWholeBoxInTheImage) {
  BoundingBox box;
  box.extend(Vec3(-1, -2, 0));
  box.extend(Vec3(3, 1, 0.5));
  for (const auto* name : {"front", "back", "left", "right", "top", "bottom", "iso"}) {
    for (const double aspect : {0.5, 1.0, 2.0}) {
      const Camera c = frame_view(parse_view(name), box, aspect);
      const Eigen::Matrix4f m = projection_matrix(c, aspect) * view_matrix(c);
      double largest = 0.0;
      for (int i = 0; i < 8; ++i) {
        const Eigen::Vector4f p((i & 1) ? 3 : -1, (i & 2) ? 1 : -2, (i & 4) ? 0.5f : 0, 1);
        const Eigen::Vector4f q = m * p;
        ASSERT_GT(q.w(), 0) << name;
        const Eigen::Vector3f ndc = q.head<3>() / q.w();
        largest = std::max<double>(largest, ndc.head<2>().cwiseAbs().maxCoeff());
        EXPECT_LE(std::abs(ndc.z()), 1.0f) << name << ": corner clipped by near/far";
      }
      // Inside the frame, and filling it (a fit, not a loose bound); 1e-5 is float round-off.
      EXPECT_LE(largest, 1.0 + 1e-5) << name;
      EXPECT_GT(largest, 0.8) << name;
    }
  }
  EXPECT_THROW(parse_view("diagonal"), UsageError);
  EXPECT_THROW(look_at(Vec3(1, 1, 1), Vec3(1, 1, 1), box), UsageError);
}

TEST(ShadingModes, ParseAndPrint) {
  for (const auto* name : {"shaded", "zebra", "isophote", "levels", "patches"}) {
    EXPECT_EQ(to_string(parse_shading_mode(name)), name);
  }
  EXPECT_THROW(parse_shading_mode("wireframe"), UsageError);
}

}  // namespace
}  // namespace stitch
