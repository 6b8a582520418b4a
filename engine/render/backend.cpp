#include "render/backend.h"

#if LAMINA_HAVE_OSMESA
#include "render/osmesa_context.h"
#endif
#if LAMINA_HAVE_EGL
#include "render/egl_context.h"
#endif

namespace lamina::render {

const std::map<std::string, Backend>& built_backends() {
  static const std::map<std::string, Backend> backends {
#if LAMINA_HAVE_OSMESA
    {"osmesa", Backend::osmesa},
#endif
#if LAMINA_HAVE_EGL
        {"egl", Backend::egl},
#endif
  };
  return backends;
}

Backend default_backend() {
  return built_backends().count("osmesa") != 0 ? Backend::osmesa : Backend::egl;
}

std::string backend_name(Backend backend) { return backend == Backend::osmesa ? "osmesa" : "egl"; }

std::unique_ptr<GlContext> open_context(Backend backend) {
#if LAMINA_HAVE_OSMESA
  if (backend == Backend::osmesa) return open_osmesa_context();
#endif
#if LAMINA_HAVE_EGL
  if (backend == Backend::egl) return open_egl_context();
#endif
  throw GlContextError("the " + backend_name(backend) + " backend is not built into Lamina");
}

}  // namespace lamina::render
