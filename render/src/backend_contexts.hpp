#pragma once
// Factories of the concrete contexts, one source file each.
#include <memory>

#include "fsi/render_context.hpp"

namespace fsi::render::detail {

std::unique_ptr<RenderContext> make_osmesa_context();
/// Throws std::runtime_error when EGL was not found at build time or fails at run time.
std::unique_ptr<RenderContext> make_egl_context();

}  // namespace fsi::render::detail
