#include "render/osmesa_context.h"

#include <GL/osmesa.h>

#include <array>
#include <cstdint>

namespace lamina::render {
namespace {

class OsMesaContext : public GlContext {
 public:
  OsMesaContext() {
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (context_ == nullptr) {
      throw GlContextError("OSMesa cannot make an OpenGL 3.3 core context; try --backend egl");
    }
    // OSMesa needs a colour buffer to make the context current; drawing goes to an FBO, so a
    // single pixel does.
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      OSMesaDestroyContext(context_);
      throw GlContextError("OSMesa cannot make its context current; try --backend egl");
    }
  }
  ~OsMesaContext() override { OSMesaDestroyContext(context_); }

  GlProc proc_address(const char* name) const override {
    return reinterpret_cast<GlProc>(OSMesaGetProcAddress(name));
  }

 private:
  OSMesaContext context_ = nullptr;
  std::array<std::uint8_t, 4> buffer_{};  // the 1×1 RGBA colour buffer OSMesa draws nothing to
};

}  // namespace

std::unique_ptr<GlContext> open_osmesa_context() { return std::make_unique<OsMesaContext>(); }

}  // namespace lamina::render
