#include "fsi/renderer.hpp"

#include "canvas.hpp"
#include "drawings.hpp"

namespace fsi::render {

struct Renderer::Impl {
  explicit Impl(GlBackend backend) : context(make_render_context(backend)), canvas(*context) {}
  std::unique_ptr<RenderContext> context;
  detail::Canvas canvas;  // after `context`: destroyed before it
};

Renderer::Renderer() : Renderer(gl_backend_from_env()) {}
Renderer::Renderer(GlBackend backend) : impl_(std::make_unique<Impl>(backend)) {}
Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

Image Renderer::render(const FieldView& view, const FrameSpec& spec) {
  Image out;
  render(view, spec, out);
  return out;
}

void Renderer::render(const FieldView& view, const FrameSpec& spec, Image& into) {
  detail::draw_field_frame(impl_->canvas, view, spec, into);
}

Image Renderer::plot(const PlotSpec& spec) { return detail::draw_plot(impl_->canvas, spec); }

GlBackend Renderer::backend() const { return impl_->context->backend(); }

Image plot(const PlotSpec& spec) { return Renderer().plot(spec); }

}  // namespace fsi::render
