// Choosing the GL backend at run time, among those this build has.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "render/gl_context.h"

namespace lamina::render {

enum class Backend { osmesa, egl };

// The backends built in, by name ("osmesa", "egl"). OSMesa comes first when built: it is
// always llvmpipe, so frames are the same on every machine with the same Mesa.
const std::map<std::string, Backend>& built_backends();
Backend default_backend();
std::string backend_name(Backend backend);

// A context of that backend, current on this thread. Throws GlContextError when the backend
// is not built in or cannot make a context.
std::unique_ptr<GlContext> open_context(Backend backend);

}  // namespace lamina::render
