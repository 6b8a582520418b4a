#include "render/egl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstring>
#include <string>

namespace lamina::render {
namespace {

std::string egl_failure(const char* what) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04X", static_cast<unsigned>(eglGetError()));
  return std::string("EGL: ") + what + " (EGL error " + code + "); try --backend osmesa";
}

bool has_client_extension(const char* name) {
  const char* extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  return extensions != nullptr && std::strstr(extensions, name) != nullptr;
}

EGLDisplay initialise_surfaceless_display() {
  if (!has_client_extension("EGL_MESA_platform_surfaceless")) {
    throw GlContextError(
        "EGL: no surfaceless platform (EGL_MESA_platform_surfaceless; install libegl-mesa0); "
        "try --backend osmesa");
  }
  EGLDisplay display =
      eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr)) {
    throw GlContextError(egl_failure("cannot open the surfaceless display"));
  }
  return display;
}

// The display is initialised once and kept until the process exits (EGL allows it): terminating
// it unloads Mesa's driver, and the next context would load and initialise it all over again.
EGLDisplay surfaceless_display() {
  static const EGLDisplay display = initialise_surfaceless_display();
  return display;
}

class EglContext : public GlContext {
 public:
  EglContext() : display_(surfaceless_display()) {
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 3,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 3,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    if (eglBindAPI(EGL_OPENGL_API)) {
      // No config and no surface: EGL_KHR_no_config_context and EGL_KHR_surfaceless_context.
      context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    }
    if (context_ == EGL_NO_CONTEXT ||
        !eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      const std::string message = egl_failure("cannot make an OpenGL 3.3 core context");
      release();
      throw GlContextError(message);
    }
  }
  ~EglContext() override { release(); }

  GlProc proc_address(const char* name) const override { return eglGetProcAddress(name); }

 private:
  void release() {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
    eglReleaseThread();
  }

  EGLDisplay display_;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlContext> open_egl_context() { return std::make_unique<EglContext>(); }

}  // namespace lamina::render
