// The EGL backend: desktop OpenGL on Mesa's surfaceless platform (no window system, no GPU
// needed: llvmpipe). Works where OSMesa is gone (Mesa 25.1 and later).
#pragma once

#include <memory>

#include "render/gl_context.h"

namespace lamina::render {

// An OpenGL 3.3 core context without a surface, made current on this thread.
// Throws GlContextError when the surfaceless display or the context cannot be made.
std::unique_ptr<GlContext> open_egl_context();

}  // namespace lamina::render
