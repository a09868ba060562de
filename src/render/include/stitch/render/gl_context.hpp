// An offscreen OpenGL 3.3 core context, for rendering without a window (command line, tests, CI).
//
// The renderer itself (renderer.hpp) only needs *a* current GL 3.3 core context; the interactive
// modeler makes its own window's context current instead of creating one of these.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

namespace stitch {

/// Raised when OpenGL cannot do what the renderer needs (no context, shader or framebuffer
/// errors). The message says which step failed and, for contexts, what to try.
class RenderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A headless EGL context (no window, no display server): Mesa's EGL_MESA_platform_surfaceless
/// first, then the default EGL display with a 1x1 pbuffer. With no GPU, Mesa falls back to its
/// software rasterizer (llvmpipe). Draw into framebuffer objects (see image.hpp): the context
/// has no default framebuffer of useful size.
class OffscreenContext {
 public:
  /// Creates the context and makes it current on this thread; throws RenderError.
  OffscreenContext();
  ~OffscreenContext();
  OffscreenContext(OffscreenContext&&) noexcept;
  OffscreenContext& operator=(OffscreenContext&&) noexcept;
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  void make_current() const;
  /// GL_RENDERER and GL_VERSION, and the EGL platform used, e.g. for --verbose output.
  [[nodiscard]] std::string description() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace stitch
