#include <gtest/gtest.h>

#include <cstdlib>
#include <fsi/image_compare.hpp>
#include <fsi/render_context.hpp>
#include <fsi/renderer.hpp>
#include <fsi/sample_field.hpp>

namespace fsi::render {
namespace {

// Sets an environment variable for one scope.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old, had_ = true;
    setenv(name, value, 1);
  }
  ~ScopedEnv() { had_ ? setenv(name_, old_.c_str(), 1) : unsetenv(name_); }

 private:
  const char* name_;
  std::string old_;
  bool had_ = false;
};

TEST(RenderContext, BackendFromEnvironment) {
  {
    ScopedEnv e("FSI_GL_BACKEND", "");
    EXPECT_EQ(gl_backend_from_env(), GlBackend::osmesa);
  }
  {
    ScopedEnv e("FSI_GL_BACKEND", "egl");
    EXPECT_EQ(gl_backend_from_env(), GlBackend::egl);
  }
  ScopedEnv e("FSI_GL_BACKEND", "vulkan");
  EXPECT_THROW(gl_backend_from_env(), std::invalid_argument);
  EXPECT_THROW(Renderer{}, std::invalid_argument);
}

TEST(RenderContext, TwoRenderersInOneThreadKeepTheirOwnContexts) {
  Renderer a{GlBackend::osmesa}, b{GlBackend::osmesa};
  FrameSpec s;
  s.width = 160;
  s.height = 120;
  const FieldView v = sample_field_view();
  const Image first = a.render(v, s);
  s.width = 200;  // b reallocates its buffer; a must be unaffected
  b.render(v, s);
  s.width = 160;
  EXPECT_TRUE(compare_images(first, a.render(v, s), 0, 0.0).same);
}

TEST(RenderContext, EglSurfacelessDrawsWhatOsmesaDraws) {
  std::unique_ptr<Renderer> egl;
  try {
    egl = std::make_unique<Renderer>(GlBackend::egl);
  } catch (const std::runtime_error& e) {
    GTEST_SKIP() << "EGL unavailable here: " << e.what();
  }
  Renderer osmesa{GlBackend::osmesa};
  FrameSpec s;
  s.width = 320;
  s.height = 240;
  s.show_mesh = true;
  const FieldView v = sample_field_view();
  const ImageComparison c = compare_images(osmesa.render(v, s), egl->render(v, s));
  EXPECT_TRUE(c.same) << c.verdict;
  EXPECT_EQ(egl->backend(), GlBackend::egl);
}

}  // namespace
}  // namespace fsi::render
