// Offscreen images: an antialiased framebuffer to draw into, reading it back, and PNG output.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "stitch/render/renderer.hpp"

namespace stitch {

/// 8-bit RGBA, rows from top to bottom.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;

  Image() = default;
  Image(int w, int h, std::uint8_t fill = 255)
      : width(w), height(h), rgba(static_cast<size_t>(w) * h * 4, fill) {}
  [[nodiscard]] std::uint8_t* pixel(int x, int y) { return &rgba[(size_t(y) * width + x) * 4]; }
  [[nodiscard]] const std::uint8_t* pixel(int x, int y) const {
    return &rgba[(size_t(y) * width + x) * 4];
  }
};

struct Antialiasing {
  int msaa_samples = 4;  ///< clamped to what the context supports
  int supersample = 2;   ///< render at this multiple of the size, then box-filter down
};

/// Renders one frame offscreen (needs the renderer's context current), the surface from
/// `blocks` when given (Renderer::draw). Throws RenderError.
Image render_image(const Renderer& renderer, const Camera& camera, const RenderStyle& style,
                   int width, int height, const Antialiasing& aa = {},
                   const SurfaceBlocks* blocks = nullptr);

/// Mean of each factor x factor block (the size must divide evenly).
Image downsample(const Image& image, int factor);
/// Images placed left to right on a `background` canvas, `gap` pixels apart, top-aligned.
Image side_by_side(const std::vector<Image>& images, int gap, std::uint8_t background = 255);

/// PNG bytes of the image (stb_image_write).
std::vector<std::uint8_t> encode_png(const Image& image);
/// Writes the PNG atomically (write_file_atomically): `path` is complete or untouched.
void write_png(const std::string& path, const Image& image);
/// The extension of the files write_png writes, the one image format stitch writes.
inline constexpr std::string_view kImageExtension = ".png";

}  // namespace stitch
