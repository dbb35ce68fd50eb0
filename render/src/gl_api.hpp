#pragma once
// The GL 1.x entry points the drawing code uses, fetched from a RenderContext so that
// nothing links libGL (OSMesa and EGL each hand out their own dispatch). GL/gl.h is
// only used for its types, constants and prototypes (for decltype), never called.
// GL_GLEXT_PROTOTYPES: prototypes (for decltype) of the entry points past GL 1.1 too,
// e.g. glBlendFuncSeparate (GL 1.4).
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>

#include "fsi/render_context.hpp"

namespace fsi::render::detail {

// X-macro list: one line per function, so the member and its loading stay in sync.
#define FSI_GL_FUNCTIONS(X)  \
  X(glBindTexture)           \
  X(glBlendFuncSeparate)     \
  X(glClear)                 \
  X(glClearColor)            \
  X(glColor4ub)              \
  X(glColorPointer)          \
  X(glDeleteTextures)        \
  X(glDisable)               \
  X(glDisableClientState)    \
  X(glDrawArrays)            \
  X(glDrawElements)          \
  X(glEnable)                \
  X(glEnableClientState)     \
  X(glGenTextures)           \
  X(glGetError)              \
  X(glGetString)             \
  X(glLoadIdentity)          \
  X(glMatrixMode)            \
  X(glOrtho)                 \
  X(glPixelStorei)           \
  X(glReadPixels)            \
  X(glScissor)               \
  X(glTexCoordPointer)       \
  X(glTexEnvi)               \
  X(glTexImage1D)            \
  X(glTexImage2D)            \
  X(glTexParameteri)         \
  X(glVertexPointer)         \
  X(glViewport)

struct GlApi {
#define FSI_GL_MEMBER(name) decltype(&::name) name = nullptr;
  FSI_GL_FUNCTIONS(FSI_GL_MEMBER)
#undef FSI_GL_MEMBER

  /// Loads every entry point; throws std::runtime_error naming a missing one. The
  /// context must be current.
  explicit GlApi(const RenderContext& context);
};

}  // namespace fsi::render::detail
