// The one shader program every frame is drawn with: pixel positions to clip space, vertex
// colour times the atlas coverage (1 on the white texel, the glyph's coverage on text).
#pragma once

#include "render/gl_api.h"

namespace lamina::render {

// Compiles and links the program. Throws GlContextError with the driver's log on failure.
GLuint make_frame_program(const GlApi& gl);

}  // namespace lamina::render
