// EGL on Mesa's surfaceless platform: a GL context with no window system at all. The
// platform offers no EGLConfigs here, so the context is made config-less
// (EGL_KHR_no_config_context), made current without a surface
// (EGL_KHR_surfaceless_context) and draws into a framebuffer object we allocate.
#include <cstdio>
#include <stdexcept>
#include <string>

#include "backend_contexts.hpp"

#ifdef FSI_RENDER_HAVE_EGL
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glext.h>
#endif

namespace fsi::render::detail {

#ifndef FSI_RENDER_HAVE_EGL

std::unique_ptr<RenderContext> make_egl_context() {
  throw std::runtime_error(
      "FSI_GL_BACKEND=egl: this fsi was built without EGL (libegl-dev not found); "
      "use FSI_GL_BACKEND=osmesa");
}

#else

namespace {

std::string egl_error(const char* what) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", unsigned(eglGetError()));
  return std::string("EGL (FSI_GL_BACKEND=egl): ") + what + " failed, error " + code;
}

bool has_extension(const char* list, const std::string& name) {
  const std::string all = std::string(" ") + (list ? list : "") + " ";
  return all.find(" " + name + " ") != std::string::npos;
}

class EglContext final : public RenderContext {
 public:
  EglContext() {
    const char* client_ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!has_extension(client_ext, "EGL_MESA_platform_surfaceless")) {
      throw std::runtime_error(
          "EGL (FSI_GL_BACKEND=egl): EGL_MESA_platform_surfaceless is not offered by this "
          "libEGL (install libegl-mesa0, or use FSI_GL_BACKEND=osmesa)");
    }
    auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!get_platform_display) throw std::runtime_error(egl_error("eglGetPlatformDisplayEXT"));
    display_ = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor)) {
      throw std::runtime_error(egl_error("eglInitialize on the surfaceless platform"));
    }
    const char* ext = eglQueryString(display_, EGL_EXTENSIONS);
    for (const char* needed : {"EGL_KHR_no_config_context", "EGL_KHR_surfaceless_context"}) {
      if (!has_extension(ext, needed)) {
        throw std::runtime_error(std::string("EGL (FSI_GL_BACKEND=egl): display lacks ") + needed);
      }
    }
    if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error(egl_error("eglBindAPI(OpenGL)"));
    const EGLint attributes[] = {EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT, EGL_NONE};
    context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context_ == EGL_NO_CONTEXT) throw std::runtime_error(egl_error("eglCreateContext"));
    try {
      bind();
      load(gen_framebuffers_, "glGenFramebuffers");
      load(bind_framebuffer_, "glBindFramebuffer");
      load(delete_framebuffers_, "glDeleteFramebuffers");
      load(gen_renderbuffers_, "glGenRenderbuffers");
      load(bind_renderbuffer_, "glBindRenderbuffer");
      load(delete_renderbuffers_, "glDeleteRenderbuffers");
      load(renderbuffer_storage_, "glRenderbufferStorage");
      load(framebuffer_renderbuffer_, "glFramebufferRenderbuffer");
      load(check_framebuffer_status_, "glCheckFramebufferStatus");
    } catch (...) {
      // The destructor does not run for a half-built object: release the context here.
      eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      eglDestroyContext(display_, context_);
      throw;
    }
  }

  ~EglContext() override {
    if (eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      if (framebuffer_) delete_framebuffers_(1, &framebuffer_);
      if (renderbuffer_) delete_renderbuffers_(1, &renderbuffer_);
    }
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    // No eglTerminate: the surfaceless display is shared by every EGL context in the
    // process, and terminating it would pull the rug from under other renderers.
  }

  void make_current(int width, int height) override {
    if (width <= 0 || height <= 0) {
      throw std::invalid_argument("EGL: bad size " + std::to_string(width) + "x" +
                                  std::to_string(height));
    }
    bind();
    if (width != width_ || height != height_) {
      if (framebuffer_) delete_framebuffers_(1, &framebuffer_);
      if (renderbuffer_) delete_renderbuffers_(1, &renderbuffer_);
      gen_renderbuffers_(1, &renderbuffer_);
      bind_renderbuffer_(GL_RENDERBUFFER, renderbuffer_);
      renderbuffer_storage_(GL_RENDERBUFFER, GL_RGBA8, width, height);
      gen_framebuffers_(1, &framebuffer_);
      bind_framebuffer_(GL_FRAMEBUFFER, framebuffer_);
      framebuffer_renderbuffer_(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                renderbuffer_);
      if (check_framebuffer_status_(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        throw std::runtime_error("EGL: framebuffer of " + std::to_string(width) + "x" +
                                 std::to_string(height) + " is incomplete");
      }
      width_ = width;
      height_ = height;
    }
    bind_framebuffer_(GL_FRAMEBUFFER, framebuffer_);
  }

  GlProc get_proc(const char* name) const override {
    // EGL_KHR_get_all_proc_addresses (Mesa): core functions are returned too.
    return reinterpret_cast<GlProc>(eglGetProcAddress(name));
  }

  GlBackend backend() const override { return GlBackend::egl; }

 private:
  void bind() {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      throw std::runtime_error(egl_error("eglMakeCurrent (surfaceless)"));
    }
  }
  template <class F>
  void load(F& f, const char* name) {
    f = reinterpret_cast<F>(eglGetProcAddress(name));
    if (!f) throw std::runtime_error(std::string("EGL: GL function missing: ") + name);
  }

  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  GLuint framebuffer_ = 0, renderbuffer_ = 0;
  int width_ = 0, height_ = 0;
  PFNGLGENFRAMEBUFFERSPROC gen_framebuffers_ = nullptr;
  PFNGLBINDFRAMEBUFFERPROC bind_framebuffer_ = nullptr;
  PFNGLDELETEFRAMEBUFFERSPROC delete_framebuffers_ = nullptr;
  PFNGLGENRENDERBUFFERSPROC gen_renderbuffers_ = nullptr;
  PFNGLBINDRENDERBUFFERPROC bind_renderbuffer_ = nullptr;
  PFNGLDELETERENDERBUFFERSPROC delete_renderbuffers_ = nullptr;
  PFNGLRENDERBUFFERSTORAGEPROC renderbuffer_storage_ = nullptr;
  PFNGLFRAMEBUFFERRENDERBUFFERPROC framebuffer_renderbuffer_ = nullptr;
  PFNGLCHECKFRAMEBUFFERSTATUSPROC check_framebuffer_status_ = nullptr;
};

}  // namespace

std::unique_ptr<RenderContext> make_egl_context() { return std::make_unique<EglContext>(); }

#endif

}  // namespace fsi::render::detail
