// OSMesa: Mesa renders (llvmpipe) straight into a buffer we own; no display, no GPU.
#include <GL/osmesa.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "backend_contexts.hpp"

namespace fsi::render::detail {
namespace {

class OsmesaContext final : public RenderContext {
 public:
  OsmesaContext() {
    // A compatibility profile: the drawing code uses client vertex arrays.
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              0,
                              OSMESA_STENCIL_BITS,
                              0,
                              OSMESA_PROFILE,
                              OSMESA_COMPAT_PROFILE,
                              0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!context_) throw std::runtime_error("OSMesa: OSMesaCreateContextAttribs failed");
  }
  ~OsmesaContext() override { OSMesaDestroyContext(context_); }

  void make_current(int width, int height) override {
    if (width <= 0 || height <= 0) {
      throw std::invalid_argument("OSMesa: bad size " + std::to_string(width) + "x" +
                                  std::to_string(height));
    }
    // Binding again is only needed when the size changed or another context (a second
    // Renderer in this thread) was made current since: frames of one movie skip it.
    if (width == width_ && height == height_ && OSMesaGetCurrentContext() == context_) return;
    if (width != width_ || height != height_) {
      buffer_.assign(std::size_t(width) * height * 4, 0);
      width_ = width;
      height_ = height;
    }
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_)) {
      throw std::runtime_error("OSMesa: OSMesaMakeCurrent failed for " + std::to_string(width) +
                               "x" + std::to_string(height));
    }
  }

  GlProc get_proc(const char* name) const override {
    return reinterpret_cast<GlProc>(OSMesaGetProcAddress(name));
  }

  GlBackend backend() const override { return GlBackend::osmesa; }

 private:
  OSMesaContext context_ = nullptr;
  std::vector<std::uint8_t> buffer_;  // the colour buffer OSMesa draws into
  int width_ = 0, height_ = 0;
};

}  // namespace

std::unique_ptr<RenderContext> make_osmesa_context() { return std::make_unique<OsmesaContext>(); }

}  // namespace fsi::render::detail
