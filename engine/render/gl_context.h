// An off-screen OpenGL context, current on the thread that created it. Backends (OSMesa, EGL)
// implement it; all drawing goes through an FBO and GL functions fetched from proc_address(),
// so the drawing code links no GL library and serves every backend.
#pragma once

#include <stdexcept>

namespace lamina::render {

using GlProc = void (*)();

class GlContext {
 public:
  virtual ~GlContext() = default;
  // The address of a GL function of this context, or nullptr when it has none.
  virtual GlProc proc_address(const char* name) const = 0;
};

// No OpenGL context could be made: the message is one line that says why and what to try.
class GlContextError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace lamina::render
