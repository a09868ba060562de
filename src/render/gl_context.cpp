#include "stitch/render/gl_context.hpp"

#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <fmt/format.h>

namespace stitch {

namespace {

std::string egl_error_name(EGLint code) {
  switch (code) {
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE:
      return "EGL_BAD_SURFACE";
    default:
      return fmt::format("EGL error 0x{:x}", code);
  }
}

constexpr EGLint kContextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                         3,
                                         EGL_CONTEXT_MINOR_VERSION,
                                         3,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                         EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_NONE};

}  // namespace

struct OffscreenContext::Impl {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  EGLSurface surface = EGL_NO_SURFACE;
  std::string platform;

  ~Impl() {
    if (display == EGL_NO_DISPLAY) return;
    if (eglGetCurrentContext() == context) {
      eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    if (surface != EGL_NO_SURFACE) eglDestroySurface(display, surface);
    if (context != EGL_NO_CONTEXT) eglDestroyContext(display, context);
    // The display is shared per process by EGL and may be in use by another context: only
    // eglReleaseThread here, never eglTerminate.
    eglReleaseThread();
  }

  // Surfaceless: no window system at all, works in containers and CI.
  bool try_surfaceless(std::string& why) {
    if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) {
      why += " EGL_MESA_platform_surfaceless is not offered;";
      return false;
    }
    display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr)) {
      why += " surfaceless display: " + egl_error_name(eglGetError()) + ";";
      display = EGL_NO_DISPLAY;
      return false;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
      why += " surfaceless: no desktop OpenGL;";
      return false;
    }
    context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, kContextAttributes);
    if (context == EGL_NO_CONTEXT) {
      why += " surfaceless context: " + egl_error_name(eglGetError()) + ";";
      return false;
    }
    platform = "EGL surfaceless";
    return true;
  }

  // Fallback for EGL implementations without the Mesa extension: default display + pbuffer.
  bool try_pbuffer(std::string& why) {
    display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr)) {
      why += " default display: " + egl_error_name(eglGetError()) + ";";
      display = EGL_NO_DISPLAY;
      return false;
    }
    eglBindAPI(EGL_OPENGL_API);
    const EGLint config_attributes[] = {EGL_SURFACE_TYPE,
                                        EGL_PBUFFER_BIT,
                                        EGL_RENDERABLE_TYPE,
                                        EGL_OPENGL_BIT,
                                        EGL_RED_SIZE,
                                        8,
                                        EGL_GREEN_SIZE,
                                        8,
                                        EGL_BLUE_SIZE,
                                        8,
                                        EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!eglChooseConfig(display, config_attributes, &config, 1, &count) || count == 0) {
      why += " default display: no pbuffer config for desktop OpenGL;";
      return false;
    }
    const EGLint pbuffer_attributes[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
    surface = eglCreatePbufferSurface(display, config, pbuffer_attributes);
    context = eglCreateContext(display, config, EGL_NO_CONTEXT, kContextAttributes);
    if (surface == EGL_NO_SURFACE || context == EGL_NO_CONTEXT) {
      why += " pbuffer context: " + egl_error_name(eglGetError()) + ";";
      return false;
    }
    platform = "EGL pbuffer";
    return true;
  }
};

OffscreenContext::OffscreenContext() : impl_(std::make_unique<Impl>()) {
  std::string why;
  if (!impl_->try_surfaceless(why)) {
    impl_ = std::make_unique<Impl>();
    if (!impl_->try_pbuffer(why)) {
      throw RenderError(fmt::format(
          "cannot create an offscreen OpenGL 3.3 core context through EGL:{} install Mesa's EGL "
          "(Debian: libegl1, libegl-mesa0, libgl1-mesa-dri) or try LIBGL_ALWAYS_SOFTWARE=1",
          why));
    }
  }
  make_current();
  if (epoxy_gl_version() < 33) {
    throw RenderError(fmt::format("the OpenGL context is version {}.{}, the renderer needs 3.3",
                                  epoxy_gl_version() / 10, epoxy_gl_version() % 10));
  }
}

OffscreenContext::~OffscreenContext() = default;
OffscreenContext::OffscreenContext(OffscreenContext&&) noexcept = default;
OffscreenContext& OffscreenContext::operator=(OffscreenContext&&) noexcept = default;

void OffscreenContext::make_current() const {
  if (!eglMakeCurrent(impl_->display, impl_->surface, impl_->surface, impl_->context)) {
    throw RenderError("eglMakeCurrent failed: " + egl_error_name(eglGetError()));
  }
}

std::string OffscreenContext::description() const {
  make_current();
  const auto text = [](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return std::string(s != nullptr ? s : "?");
  };
  return fmt::format("{} | OpenGL {} | {}", text(GL_RENDERER), text(GL_VERSION), impl_->platform);
}

}  // namespace stitch
