#include "canvas.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace fsi::render::detail {

Canvas::Canvas(RenderContext& context)
    : context_((context.make_current(1, 1), context)), gl_(context) {}

Canvas::~Canvas() {
  // The context may already be unusable during stack unwinding; never throw here.
  try {
    context_.make_current(std::max(width_ * supersample_, 1), std::max(height_ * supersample_, 1));
    for (unsigned t : textures_) {
      if (t) gl_.glDeleteTextures(1, &t);
    }
  } catch (...) {
  }
}

void Canvas::begin(int width, int height, int supersample, Rgba bg) {
  if (width <= 0 || height <= 0 || supersample < 1 || supersample > 4) {
    throw std::invalid_argument("Canvas: bad size " + std::to_string(width) + "x" +
                                std::to_string(height) + " or supersample " +
                                std::to_string(supersample));
  }
  width_ = width;
  height_ = height;
  supersample_ = supersample;
  context_.make_current(width * supersample, height * supersample);
  gl_.glViewport(0, 0, width * supersample, height * supersample);
  gl_.glMatrixMode(GL_PROJECTION);
  gl_.glLoadIdentity();
  // Logical pixels, y down: the top row of the picture is the top of the framebuffer.
  gl_.glOrtho(0.0, width, height, 0.0, -1.0, 1.0);
  gl_.glMatrixMode(GL_MODELVIEW);
  gl_.glLoadIdentity();
  gl_.glDisable(GL_DEPTH_TEST);
  gl_.glDisable(GL_CULL_FACE);
  gl_.glDisable(GL_SCISSOR_TEST);
  gl_.glEnable(GL_BLEND);
  gl_.glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  gl_.glClearColor(bg.r / 255.f, bg.g / 255.f, bg.b / 255.f, bg.a / 255.f);
  gl_.glClear(GL_COLOR_BUFFER_BIT);
}

Image Canvas::finish() {
  const int s = supersample_, fw = width_ * s, fh = height_ * s;
  std::vector<std::uint8_t> fb(std::size_t(fw) * fh * 4);
  gl_.glFinish();
  gl_.glPixelStorei(GL_PACK_ALIGNMENT, 1);
  gl_.glReadPixels(0, 0, fw, fh, GL_RGBA, GL_UNSIGNED_BYTE, fb.data());
  if (const GLenum e = gl_.glGetError(); e != GL_NO_ERROR) {
    throw std::runtime_error("Canvas: OpenGL error " + std::to_string(e) + " while drawing");
  }
  Image out{width_, height_, std::vector<std::uint8_t>(std::size_t(width_) * height_ * 4)};
  const unsigned n = unsigned(s * s);
  for (int y = 0; y < height_; ++y) {
    std::uint8_t* dst = out.rgba.data() + out.offset(0, y);
    for (int x = 0; x < width_; ++x, dst += 4) {
      unsigned sum[4] = {0, 0, 0, 0};
      for (int j = 0; j < s; ++j) {
        // GL rows run bottom-up: logical row y covers framebuffer rows fh-1-(y*s+j).
        const std::uint8_t* src = fb.data() + (std::size_t(fh - 1 - (y * s + j)) * fw + x * s) * 4;
        for (int i = 0; i < s; ++i, src += 4) {
          for (int c = 0; c < 4; ++c) sum[c] += src[c];
        }
      }
      for (int c = 0; c < 4; ++c) dst[c] = std::uint8_t((sum[c] + n / 2) / n);
    }
  }
  return out;
}

void Canvas::clip(const Rect& r) {
  const int s = supersample_;
  const int x0 = int(std::floor(r.x0 * s)), x1 = int(std::ceil(r.x1 * s));
  const int top = int(std::floor(r.y0 * s)), bottom = int(std::ceil(r.y1 * s));
  gl_.glEnable(GL_SCISSOR_TEST);
  gl_.glScissor(x0, height_ * s - bottom, std::max(x1 - x0, 0), std::max(bottom - top, 0));
}

void Canvas::clear_clip() { gl_.glDisable(GL_SCISSOR_TEST); }

void Canvas::triangles(const std::vector<Vec2>& v, Rgba c) {
  if (v.empty()) return;
  gl_.glColor4ub(c.r, c.g, c.b, c.a);
  gl_.glEnableClientState(GL_VERTEX_ARRAY);
  gl_.glVertexPointer(2, GL_FLOAT, sizeof(Vec2), v.data());
  gl_.glDrawArrays(GL_TRIANGLES, 0, GLsizei(v.size()));
  gl_.glDisableClientState(GL_VERTEX_ARRAY);
}

void Canvas::fill_rect(const Rect& r, Rgba c) {
  triangles({{r.x0, r.y0}, {r.x1, r.y0}, {r.x1, r.y1}, {r.x0, r.y0}, {r.x1, r.y1}, {r.x0, r.y1}},
            c);
}

void Canvas::stroke_rect(const Rect& r, float w, Rgba c) {
  // Four bars that overlap at the corners (no gaps, no double blending for opaque ink).
  const float h = w / 2;
  fill_rect({r.x0 - h, r.y0 - h, r.x1 + h, r.y0 + h}, c);
  fill_rect({r.x0 - h, r.y1 - h, r.x1 + h, r.y1 + h}, c);
  fill_rect({r.x0 - h, r.y0 + h, r.x0 + h, r.y1 - h}, c);
  fill_rect({r.x1 - h, r.y0 + h, r.x1 + h, r.y1 - h}, c);
}

void Canvas::segments(const std::vector<Vec2>& p, float w, Rgba c, bool round_joins) {
  std::vector<Vec2> v;
  v.reserve(p.size() / 2 * 6 + (round_joins ? p.size() * 24 : 0));
  const float h = w / 2;
  for (std::size_t k = 0; k + 1 < p.size(); k += 2) {
    const Vec2 a = p[k], b = p[k + 1];
    const float dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
    if (len > 0) {
      const float nx = -dy / len * h, ny = dx / len * h;
      const Vec2 a1{a.x + nx, a.y + ny}, a2{a.x - nx, a.y - ny}, b1{b.x + nx, b.y + ny},
          b2{b.x - nx, b.y - ny};
      v.insert(v.end(), {a1, b1, b2, a1, b2, a2});
    }
    if (round_joins) {
      // An octagon at each end: enough for widths of a few pixels.
      constexpr int sides = 8;
      for (const Vec2 centre : {a, b}) {
        for (int i = 0; i < sides; ++i) {
          const float t0 = 2 * std::numbers::pi_v<float> * i / sides;
          const float t1 = 2 * std::numbers::pi_v<float> * (i + 1) / sides;
          v.insert(v.end(), {centre,
                             {centre.x + h * std::cos(t0), centre.y + h * std::sin(t0)},
                             {centre.x + h * std::cos(t1), centre.y + h * std::sin(t1)}});
        }
      }
    }
  }
  // Translucent ink shows overlaps (the joins) a little darker: fine for the faint
  // mesh overlay, the only translucent caller.
  triangles(v, c);
}

void Canvas::polyline(const std::vector<Vec2>& points, float w, Rgba c) {
  std::vector<Vec2> pairs;
  pairs.reserve(points.size() * 2);
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    pairs.push_back(points[i]);
    pairs.push_back(points[i + 1]);
  }
  segments(pairs, w, c, true);
}

unsigned Canvas::texture(Colormap map) {
  unsigned& tex = textures_[static_cast<std::size_t>(map)];
  if (tex) return tex;
  const ColormapTable table = colormap_table(map);
  std::vector<std::uint8_t> rgba;
  for (const Rgb8& c : table) rgba.insert(rgba.end(), {c.r, c.g, c.b, 255});
  gl_.glGenTextures(1, &tex);
  gl_.glBindTexture(GL_TEXTURE_1D, tex);
  gl_.glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl_.glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA8, colormap_size, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                   rgba.data());
  // Linear between neighbouring entries, clamped at the ends: out-of-range values
  // saturate per pixel instead of wrapping around.
  gl_.glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  gl_.glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  gl_.glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  return tex;
}

namespace {
// Maps t in [0, 1] onto the centres of the first and last texels, so t = 0 and t = 1
// give exactly the end colours of the table.
float texel(float t) { return (0.5f + t * (colormap_size - 1)) / colormap_size; }
}  // namespace

void Canvas::scalar_triangles(const std::vector<Vec2>& positions, const std::vector<float>& t,
                              const std::vector<unsigned>& indices, Colormap map) {
  if (indices.empty()) return;
  std::vector<float> s(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    // NaN would poison the interpolation; far-out values are clamped to keep floats sane
    // (the texture clamps per pixel anyway).
    s[i] = std::isfinite(t[i]) ? texel(std::clamp(t[i], -1e3f, 1e3f)) : texel(0.5f);
  }
  gl_.glEnable(GL_TEXTURE_1D);
  gl_.glBindTexture(GL_TEXTURE_1D, texture(map));
  gl_.glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  gl_.glEnableClientState(GL_VERTEX_ARRAY);
  gl_.glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  gl_.glVertexPointer(2, GL_FLOAT, sizeof(Vec2), positions.data());
  gl_.glTexCoordPointer(1, GL_FLOAT, 0, s.data());
  gl_.glDrawElements(GL_TRIANGLES, GLsizei(indices.size()), GL_UNSIGNED_INT, indices.data());
  gl_.glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  gl_.glDisableClientState(GL_VERTEX_ARRAY);
  gl_.glDisable(GL_TEXTURE_1D);
}

void Canvas::colormap_rect(const Rect& r, Colormap map) {
  scalar_triangles({{r.x0, r.y1}, {r.x1, r.y1}, {r.x1, r.y0}, {r.x0, r.y0}}, {0, 0, 1, 1},
                   {0, 1, 2, 0, 2, 3}, map);
}

}  // namespace fsi::render::detail
