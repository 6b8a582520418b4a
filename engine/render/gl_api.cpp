#include "render/gl_api.h"

#include <string>

namespace lamina::render {
namespace {

template <typename Function>
void load(Function& entry, const GlContext& context, const char* name) {
  entry = reinterpret_cast<Function>(context.proc_address(name));
  if (entry == nullptr) {
    throw GlContextError(std::string("the OpenGL context has no ") + name +
                         " (Lamina needs OpenGL 3.3 core)");
  }
}

}  // namespace

GlApi::GlApi(const GlContext& context) {
#define LAMINA_GL_LOAD(type, name) load(name, context, "gl" #name);
  LAMINA_GL_FUNCTIONS(LAMINA_GL_LOAD)
#undef LAMINA_GL_LOAD
}

}  // namespace lamina::render
