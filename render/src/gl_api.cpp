#include "gl_api.hpp"

#include <stdexcept>
#include <string>

namespace fsi::render::detail {

GlApi::GlApi(const RenderContext& context) {
#define FSI_GL_LOAD(name)                                                      \
  name = reinterpret_cast<decltype(name)>(context.get_proc(#name));            \
  if (!name) {                                                                 \
    throw std::runtime_error(std::string(gl_backend_name(context.backend())) + \
                             ": OpenGL function " #name " is not available");  \
  }
  FSI_GL_FUNCTIONS(FSI_GL_LOAD)
#undef FSI_GL_LOAD
}

}  // namespace fsi::render::detail
