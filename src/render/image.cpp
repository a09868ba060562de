#include "stitch/render/image.hpp"

#include <epoxy/gl.h>
#include <fmt/format.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cstring>

#include "stitch/error.hpp"
#include "stitch/render/gl_context.hpp"

namespace stitch {

namespace {

// A framebuffer with colour and depth renderbuffers, deleted with it.
struct Framebuffer {
  GLuint fbo = 0, colour = 0, depth = 0;

  Framebuffer(int width, int height, int samples, bool with_depth) {
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glGenRenderbuffers(1, &colour);
    glBindRenderbuffer(GL_RENDERBUFFER, colour);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
    if (with_depth) {
      glGenRenderbuffers(1, &depth);
      glBindRenderbuffer(GL_RENDERBUFFER, depth);
      glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width,
                                       height);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    }
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
      release();
      throw RenderError(
          fmt::format("cannot create a {}x{} framebuffer with {} samples (status 0x{:x})", width,
                      height, samples, status));
    }
  }
  ~Framebuffer() { release(); }
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;

  void release() {
    if (depth != 0) glDeleteRenderbuffers(1, &depth);
    if (colour != 0) glDeleteRenderbuffers(1, &colour);
    if (fbo != 0) glDeleteFramebuffers(1, &fbo);
    fbo = colour = depth = 0;
  }
};

}  // namespace

Image render_image(const Renderer& renderer, const Camera& camera, const RenderStyle& style,
                   int width, int height, const Antialiasing& aa, const SurfaceBlocks* blocks) {
  if (width < 1 || height < 1) {
    throw UsageError(fmt::format("image size {}x{} is empty", width, height));
  }
  GLint max_samples = 1, max_size = 0, previous_fbo = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous_fbo);
  if (width > max_size || height > max_size) {
    throw UsageError(
        fmt::format("image size {}x{} exceeds the OpenGL limit of {}", width, height, max_size));
  }
  int factor = std::max(1, aa.supersample);
  while (factor > 1 && std::max(width, height) * factor > max_size) --factor;
  const int w = width * factor, h = height * factor;
  const int samples = std::clamp(aa.msaa_samples, 0, static_cast<int>(max_samples));

  // Errors left by earlier GL calls of the application are not ours to report.
  while (glGetError() != GL_NO_ERROR) {
  }
  Image image(w, h);
  {
    // Whatever happens, leave the application's framebuffer bound as it was.
    struct RestoreBinding {
      GLint fbo;
      ~RestoreBinding() { glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(fbo)); }
    } restore{previous_fbo};
    Framebuffer target(w, h, samples, true);
    renderer.draw(camera, style, w, h, static_cast<float>(factor), blocks);
    // Resolve the samples into a single-sample framebuffer, then read it.
    Framebuffer resolved(w, h, 0, false);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, target.fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved.fbo);
    glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved.fbo);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    std::vector<std::uint8_t> bottom_up(image.rgba.size());
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.data());
    const size_t row = static_cast<size_t>(w) * 4;
    for (int y = 0; y < h; ++y) {
      std::memcpy(&image.rgba[y * row], &bottom_up[(h - 1 - y) * row], row);
    }
  }
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    throw RenderError(fmt::format("OpenGL error 0x{:x} while rendering", error));
  }
  // The picture is opaque whatever the blending left in the alpha channel.
  for (size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255;
  return factor > 1 ? downsample(image, factor) : image;
}

Image downsample(const Image& image, int factor) {
  if (factor < 1 || image.width % factor != 0 || image.height % factor != 0) {
    throw std::invalid_argument(
        fmt::format("cannot downsample {}x{} by {}", image.width, image.height, factor));
  }
  Image out(image.width / factor, image.height / factor);
  const int n = factor * factor;
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      std::array<int, 4> sum{};
      for (int dy = 0; dy < factor; ++dy) {
        for (int dx = 0; dx < factor; ++dx) {
          const std::uint8_t* p = image.pixel(x * factor + dx, y * factor + dy);
          for (int c = 0; c < 4; ++c) sum[c] += p[c];
        }
      }
      std::uint8_t* q = out.pixel(x, y);
      for (int c = 0; c < 4; ++c) q[c] = static_cast<std::uint8_t>((sum[c] + n / 2) / n);
    }
  }
  return out;
}

Image side_by_side(const std::vector<Image>& images, int gap, std::uint8_t background) {
  int width = 0, height = 0;
  for (const Image& im : images) {
    width += im.width;
    height = std::max(height, im.height);
  }
  if (!images.empty()) width += gap * static_cast<int>(images.size() - 1);
  Image out(width, height, background);
  for (size_t i = 3; i < out.rgba.size(); i += 4) out.rgba[i] = 255;
  int x0 = 0;
  for (const Image& im : images) {
    for (int y = 0; y < im.height; ++y) {
      std::memcpy(out.pixel(x0, y), im.pixel(0, y), static_cast<size_t>(im.width) * 4);
    }
    x0 += im.width + gap;
  }
  return out;
}

std::vector<std::uint8_t> encode_png(const Image& image) {
  std::vector<std::uint8_t> bytes;
  const auto append = [](void* context, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    const auto* p = static_cast<const std::uint8_t*>(data);
    out->insert(out->end(), p, p + size);
  };
  if (image.width < 1 || image.height < 1 ||
      stbi_write_png_to_func(append, &bytes, image.width, image.height, 4, image.rgba.data(),
                             image.width * 4) == 0) {
    throw RenderError(
        fmt::format("PNG encoding of a {}x{} image failed", image.width, image.height));
  }
  return bytes;
}

}  // namespace stitch
