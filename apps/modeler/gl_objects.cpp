#include "gl_objects.hpp"

#include <algorithm>

#include "stitch/render/gl_context.hpp"

namespace stitch::modeler::app {

namespace {

void attach(GLuint framebuffer, GLenum attachment, GLuint renderbuffer) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, attachment, GL_RENDERBUFFER, renderbuffer);
}

void require_complete(const char* which) {
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw RenderError(std::string("the 3D view's ") + which + " framebuffer is incomplete");
}

}  // namespace

void OffscreenTarget::resize(int width, int height) {
  if (allocated_ && width == width_ && height == height_) return;
  buffers_ = Buffers{};  // the old names are deleted by their owners
  allocated_ = true;
  width_ = width;
  height_ = height;
  GLint most_samples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &most_samples);
  const GLsizei samples = std::min<GLint>(4, most_samples);
  glBindRenderbuffer(GL_RENDERBUFFER, buffers_.colour.id());
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, buffers_.depth.id());
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, buffers_.resolved_colour.id());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  attach(buffers_.drawn.id(), GL_COLOR_ATTACHMENT0, buffers_.colour.id());
  attach(buffers_.drawn.id(), GL_DEPTH_ATTACHMENT, buffers_.depth.id());
  require_complete("multisampled");
  attach(buffers_.resolved.id(), GL_COLOR_ATTACHMENT0, buffers_.resolved_colour.id());
  require_complete("resolved");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void OffscreenTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, buffers_.drawn.id());
}

void OffscreenTarget::present(int x, int y) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, buffers_.drawn.id());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, buffers_.resolved.id());
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, buffers_.resolved.id());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBlitFramebuffer(0, 0, width_, height_, x, y, x + width_, y + height_, GL_COLOR_BUFFER_BIT,
                    GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace stitch::modeler::app
