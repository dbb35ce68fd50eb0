#pragma once
/// \file render_context.hpp
/// An offscreen OpenGL context: the only place that knows about OSMesa or EGL. The
/// drawing code gets GL entry points through get_proc(), never by linking a libGL, so
/// the two backends can live in one process without fighting over gl* symbols.
#include <memory>
#include <string_view>

namespace fsi::render {

/// Which library gives us OpenGL.
enum class GlBackend {
  osmesa,  ///< Mesa's software OSMesa (default; needs nothing but libOSMesa)
  egl,     ///< EGL surfaceless platform (EGL_MESA_platform_surfaceless) + framebuffer object
};

/// The backend named by the environment variable FSI_GL_BACKEND ("osmesa" or "egl");
/// osmesa when unset or empty. Throws std::invalid_argument on any other value.
GlBackend gl_backend_from_env();

std::string_view gl_backend_name(GlBackend backend);

/// One GL context with a colour buffer of width x height pixels (8-bit RGBA).
/// Not copyable; not thread-safe (use one per thread).
class RenderContext {
 public:
  using GlProc = void (*)();

  virtual ~RenderContext() = default;
  RenderContext(const RenderContext&) = delete;
  RenderContext& operator=(const RenderContext&) = delete;

  /// Makes the context current on this thread with a drawable of at least
  /// width x height pixels [px], reallocating it when the size changed. Throws
  /// std::runtime_error when the backend refuses.
  virtual void make_current(int width, int height) = 0;

  /// A GL function by name ("glDrawElements"), or nullptr when unavailable.
  virtual GlProc get_proc(const char* name) const = 0;

  virtual GlBackend backend() const = 0;

 protected:
  RenderContext() = default;
};

/// Creates a context of the given backend. Throws std::runtime_error with the reason
/// (e.g. "EGL: no surfaceless platform") when the backend cannot start.
std::unique_ptr<RenderContext> make_render_context(GlBackend backend);

/// make_render_context(gl_backend_from_env()).
std::unique_ptr<RenderContext> make_render_context();

}  // namespace fsi::render
