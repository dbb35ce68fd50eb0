#include "fsi/render_context.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string>

#include "backend_contexts.hpp"

namespace fsi::render {

GlBackend gl_backend_from_env() {
  const char* value = std::getenv("FSI_GL_BACKEND");
  const std::string v = value ? value : "";
  if (v.empty() || v == "osmesa") return GlBackend::osmesa;
  if (v == "egl") return GlBackend::egl;
  throw std::invalid_argument("FSI_GL_BACKEND: must be 'osmesa' or 'egl', got '" + v + "'");
}

std::string_view gl_backend_name(GlBackend backend) {
  return backend == GlBackend::osmesa ? "osmesa" : "egl";
}

std::unique_ptr<RenderContext> make_render_context(GlBackend backend) {
  switch (backend) {
    case GlBackend::osmesa:
      return detail::make_osmesa_context();
    case GlBackend::egl:
      return detail::make_egl_context();
  }
  throw std::invalid_argument("unknown GL backend");
}

std::unique_ptr<RenderContext> make_render_context() {
  return make_render_context(gl_backend_from_env());
}

}  // namespace fsi::render
