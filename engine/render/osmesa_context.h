// The OSMesa backend: Mesa's off-screen library (libOSMesa, llvmpipe). Mesa 25.1 removed it;
// the EGL backend takes its place there.
#pragma once

#include <memory>

#include "render/gl_context.h"

namespace lamina::render {

// An OpenGL 3.3 core context made current on this thread.
// Throws GlContextError when OSMesa cannot make one.
std::unique_ptr<GlContext> open_osmesa_context();

}  // namespace lamina::render
