// OpenGL objects owned by C++ values: each name is deleted by its owner's destructor, so no GL
// object of the modeler is freed by hand. Needs a current context for the whole lifetime.
#pragma once

#include <epoxy/gl.h>

#include <utility>

namespace stitch::modeler::app {

/// One GL name of the kind `Kind` (Kind::create / Kind::destroy), unique and movable.
template <class Kind>
class GlHandle {
 public:
  GlHandle() { Kind::create(&id_); }
  ~GlHandle() {
    if (id_) Kind::destroy(id_);
  }
  GlHandle(GlHandle&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  GlHandle& operator=(GlHandle&& other) noexcept {
    if (this != &other) {
      if (id_) Kind::destroy(id_);
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }
  GlHandle(const GlHandle&) = delete;
  GlHandle& operator=(const GlHandle&) = delete;
  [[nodiscard]] GLuint id() const { return id_; }

 private:
  GLuint id_ = 0;
};

struct FramebufferKind {
  static void create(GLuint* id) { glGenFramebuffers(1, id); }
  static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); }
};
struct RenderbufferKind {
  static void create(GLuint* id) { glGenRenderbuffers(1, id); }
  static void destroy(GLuint id) { glDeleteRenderbuffers(1, &id); }
};
using Framebuffer = GlHandle<FramebufferKind>;
using Renderbuffer = GlHandle<RenderbufferKind>;

/// A colour + depth framebuffer the 3D view is drawn into, multisampled when the GL has
/// samples, with a single-sampled copy to resolve into: GL 3.3 resolves multisamples only to
/// the same rectangle, and the view sits beside the panels, not at the window's origin.
class OffscreenTarget {
 public:
  /// Makes the buffers width x height (no-op when they already are).
  void resize(int width, int height);
  /// Binds the multisampled framebuffer for drawing.
  void bind() const;
  /// Resolves the samples and copies the picture to the window's framebuffer at (x, y) (GL
  /// coordinates: from the bottom left).
  void present(int x, int y) const;
  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }

 private:
  struct Buffers {
    Framebuffer drawn, resolved;
    Renderbuffer colour, depth, resolved_colour;
  };
  Buffers buffers_;
  bool allocated_ = false;
  int width_ = 0, height_ = 0;
};

}  // namespace stitch::modeler::app
