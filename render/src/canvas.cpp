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
    for (const auto& [size, t] : glyph_textures_) gl_.glDeleteTextures(1, &t);
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
  // Logical pixels, y down, onto GL's window rows bottom-up: logical row 0 lands in the
  // framebuffer's row 0, the first in memory, so glReadPixels hands back the picture
  // top row first.
  gl_.glOrtho(0.0, width, 0.0, height, -1.0, 1.0);
  gl_.glMatrixMode(GL_MODELVIEW);
  gl_.glLoadIdentity();
  gl_.glDisable(GL_DEPTH_TEST);
  gl_.glDisable(GL_CULL_FACE);
  gl_.glDisable(GL_SCISSOR_TEST);
  // Colour over the paper by the ink's alpha; the paper's alpha composited "over" as
  // well (srcA + dstA (1 - srcA)), so opaque paper stays opaque. glBlendFunc would write
  // srcA^2 + dstA (1 - srcA): 0.75 where a half-covered edge pixel lies on opaque paper,
  // and the PNG of an opaque frame would come out translucent at every antialiased edge.
  gl_.glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  gl_.glDisable(GL_BLEND);
  blending_ = false;
  gl_.glClearColor(bg.r / 255.f, bg.g / 255.f, bg.b / 255.f, bg.a / 255.f);
  gl_.glClear(GL_COLOR_BUFFER_BIT);
}

void Canvas::set_blending(bool on) {
  // Opaque fills (most of the picture: the field, bars, opaque lines' cores) skip the
  // read-modify-write of blending.
  if (on == blending_) return;
  on ? gl_.glEnable(GL_BLEND) : gl_.glDisable(GL_BLEND);
  blending_ = on;
}

void Canvas::finish(Image& out) {
  const int s = supersample_, fw = width_ * s, fh = height_ * s;
  out.width = width_;
  out.height = height_;
  out.rgba.resize(std::size_t(width_) * height_ * 4);
  gl_.glPixelStorei(GL_PACK_ALIGNMENT, 1);
  if (s == 1) {
    gl_.glReadPixels(0, 0, fw, fh, GL_RGBA, GL_UNSIGNED_BYTE, out.rgba.data());
  } else {
    framebuffer_.resize(std::size_t(fw) * fh * 4);
    gl_.glReadPixels(0, 0, fw, fh, GL_RGBA, GL_UNSIGNED_BYTE, framebuffer_.data());
  }
  if (const GLenum e = gl_.glGetError(); e != GL_NO_ERROR) {
    throw std::runtime_error("Canvas: OpenGL error " + std::to_string(e) + " while drawing");
  }
  if (s == 1) return;
  const unsigned n = unsigned(s * s);
  for (int y = 0; y < height_; ++y) {
    std::uint8_t* dst = out.rgba.data() + out.offset(0, y);
    for (int x = 0; x < width_; ++x, dst += 4) {
      unsigned sum[4] = {0, 0, 0, 0};
      for (int j = 0; j < s; ++j) {
        const std::uint8_t* src = framebuffer_.data() + (std::size_t(y * s + j) * fw + x * s) * 4;
        for (int i = 0; i < s; ++i, src += 4) {
          for (int c = 0; c < 4; ++c) sum[c] += src[c];
        }
      }
      for (int c = 0; c < 4; ++c) dst[c] = std::uint8_t((sum[c] + n / 2) / n);
    }
  }
}

void Canvas::clip(const Rect& r) {
  const int s = supersample_;
  const int x0 = int(std::floor(r.x0 * s)), x1 = int(std::ceil(r.x1 * s));
  const int top = int(std::floor(r.y0 * s)), bottom = int(std::ceil(r.y1 * s));
  gl_.glEnable(GL_SCISSOR_TEST);
  gl_.glScissor(x0, top, std::max(x1 - x0, 0), std::max(bottom - top, 0));
}

void Canvas::clear_clip() { gl_.glDisable(GL_SCISSOR_TEST); }

void Canvas::triangles(const std::vector<Vec2>& v, Rgba c) {
  if (v.empty()) return;
  set_blending(c.a < 255);
  gl_.glColor4ub(c.r, c.g, c.b, c.a);
  gl_.glEnableClientState(GL_VERTEX_ARRAY);
  gl_.glVertexPointer(2, GL_FLOAT, sizeof(Vec2), v.data());
  gl_.glDrawArrays(GL_TRIANGLES, 0, GLsizei(v.size()));
  gl_.glDisableClientState(GL_VERTEX_ARRAY);
}

void Canvas::coloured_triangles(const std::vector<ColouredVertex>& v) {
  if (v.empty()) return;
  set_blending(true);
  gl_.glEnableClientState(GL_VERTEX_ARRAY);
  gl_.glEnableClientState(GL_COLOR_ARRAY);
  gl_.glVertexPointer(2, GL_FLOAT, sizeof(ColouredVertex), &v[0].x);
  gl_.glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(ColouredVertex), &v[0].r);
  gl_.glDrawArrays(GL_TRIANGLES, 0, GLsizei(v.size()));
  gl_.glDisableClientState(GL_COLOR_ARRAY);
  gl_.glDisableClientState(GL_VERTEX_ARRAY);
}

Rect Canvas::snapped(const Rect& r) const {
  const float s = float(supersample_);
  float x0 = std::round(r.x0 * s), x1 = std::round(r.x1 * s);
  float y0 = std::round(r.y0 * s), y1 = std::round(r.y1 * s);
  if (x1 <= x0) x1 = x0 + 1;
  if (y1 <= y0) y1 = y0 + 1;
  return {x0 / s, y0 / s, x1 / s, y1 / s};
}

Rect Canvas::snapped_bar(float c, float from, float to, float w, bool vertical) const {
  // The width is rounded first, then the position: every bar of one width is equally
  // wide wherever it falls (a frame's four sides match).
  const float s = float(supersample_);
  const float wpx = std::max(1.0f, std::round(w * s));
  const float lo = std::round(c * s - wpx / 2) / s, hi = lo + wpx / s;
  const float a = std::round(std::min(from, to) * s) / s,
              b = std::round(std::max(from, to) * s) / s;
  return vertical ? Rect{lo, a, hi, std::max(b, a + 1 / s)}
                  : Rect{a, lo, std::max(b, a + 1 / s), hi};
}

void Canvas::fill_rect(const Rect& r, Rgba c) {
  const Rect q = snapped(r);
  vertices_.assign(
      {{q.x0, q.y0}, {q.x1, q.y0}, {q.x1, q.y1}, {q.x0, q.y0}, {q.x1, q.y1}, {q.x0, q.y1}});
  triangles(vertices_, c);
}

void Canvas::stroke_rect(const Rect& r, float w, Rgba c) {
  // Four snapped bars that overlap at the corners (no gaps; translucent ink would show
  // the corners darker, no caller uses it).
  const float h = w / 2;
  for (const Rect& bar : {snapped_bar(r.y0, r.x0 - h, r.x1 + h, w, false),
                          snapped_bar(r.y1, r.x0 - h, r.x1 + h, w, false),
                          snapped_bar(r.x0, r.y0 - h, r.y1 + h, w, true),
                          snapped_bar(r.x1, r.y0 - h, r.y1 + h, w, true)}) {
    fill_rect(bar, c);
  }
}

void Canvas::segments(const std::vector<Vec2>& p, float w, Rgba c, bool round_joins) {
  // Each segment is a quad of full ink (the core) with a fringe one framebuffer pixel
  // wide on each side whose alpha falls to zero: a coverage ramp, i.e. antialiasing.
  // Lines thinner than the fringe are drawn one fringe wide with their ink scaled by
  // the width, which keeps their coverage. Axis-aligned segments without joins (ticks,
  // grid lines) are snapped bars instead: crisp.
  const float f = 1.0f / float(supersample_);
  const float we = std::max(w, f);
  const Rgba full{c.r, c.g, c.b, std::uint8_t(std::lround(c.a * std::min(1.0f, w / f)))};
  const Rgba none{c.r, c.g, c.b, 0};
  const float core = we / 2 - f / 2, outer = we / 2 + f / 2;
  coloured_.clear();
  auto push = [this](Vec2 v, Rgba col) {
    coloured_.push_back({v.x, v.y, col.r, col.g, col.b, col.a});
  };
  auto quad = [&](Vec2 a, Vec2 b, Vec2 cc, Vec2 d, Rgba ab, Rgba cd) {
    // a-b one long side (colour ab), d-cc the other (colour cd); a opposite d.
    push(a, ab), push(b, ab), push(cc, cd), push(a, ab), push(cc, cd), push(d, cd);
  };
  Vec2 last_end{NAN, NAN};  // a join drawn already (chained segments share their ends)
  for (std::size_t k = 0; k + 1 < p.size(); k += 2) {
    const Vec2 a = p[k], b = p[k + 1];
    const float dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
    if (!round_joins && (dx == 0 || dy == 0) && len > 0) {
      const bool vertical = dx == 0;
      const Rect bar =
          vertical ? snapped_bar(a.x, a.y, b.y, w, true) : snapped_bar(a.y, a.x, b.x, w, false);
      const Rgba ink = w < f ? full : c;
      for (const Vec2 v : {Vec2{bar.x0, bar.y0}, Vec2{bar.x1, bar.y0}, Vec2{bar.x1, bar.y1},
                           Vec2{bar.x0, bar.y0}, Vec2{bar.x1, bar.y1}, Vec2{bar.x0, bar.y1}}) {
        push(v, ink);
      }
      continue;
    }
    if (len > 0) {
      const float nx = -dy / len, ny = dx / len;
      auto off = [&](Vec2 q, float d) { return Vec2{q.x + nx * d, q.y + ny * d}; };
      if (core > 0) quad(off(a, core), off(b, core), off(b, -core), off(a, -core), full, full);
      quad(off(a, core), off(b, core), off(b, outer), off(a, outer), full, none);
      quad(off(a, -core), off(b, -core), off(b, -outer), off(a, -outer), full, none);
    }
    if (round_joins) {
      // A disc at each end (core and fringe ring) hides the notches where segments meet.
      const int sides = std::clamp(int(std::ceil(outer * supersample_ * 2.5f)), 8, 32);
      const bool a_drawn = a.x == last_end.x && a.y == last_end.y;
      last_end = b;
      for (const Vec2 centre : {a, b}) {
        if (a_drawn && centre.x == a.x && centre.y == a.y) continue;
        for (int i = 0; i < sides; ++i) {
          const float t0 = 2 * std::numbers::pi_v<float> * i / sides;
          const float t1 = 2 * std::numbers::pi_v<float> * (i + 1) / sides;
          const Vec2 u0{std::cos(t0), std::sin(t0)}, u1{std::cos(t1), std::sin(t1)};
          auto at = [&](Vec2 u, float r) { return Vec2{centre.x + u.x * r, centre.y + u.y * r}; };
          if (core > 0) push(centre, full), push(at(u0, core), full), push(at(u1, core), full);
          quad(at(u0, core), at(u1, core), at(u1, outer), at(u0, outer), full, none);
        }
      }
    }
  }
  coloured_triangles(coloured_);
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
  // The nearest of the 256 entries (linear filtering between them cost 0.8 ms more per
  // 1280x720 frame for no visible change), clamped at the ends: out-of-range values
  // saturate per pixel instead of wrapping around.
  gl_.glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl_.glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
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
  texcoords_.resize(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    // NaN would poison the interpolation; far-out values are clamped to keep floats sane
    // (the texture clamps per pixel anyway).
    texcoords_[i] = std::isfinite(t[i]) ? texel(std::clamp(t[i], -1e3f, 1e3f)) : texel(0.5f);
  }
  set_blending(false);
  gl_.glEnable(GL_TEXTURE_1D);
  gl_.glBindTexture(GL_TEXTURE_1D, texture(map));
  gl_.glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  gl_.glEnableClientState(GL_VERTEX_ARRAY);
  gl_.glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  gl_.glVertexPointer(2, GL_FLOAT, sizeof(Vec2), positions.data());
  gl_.glTexCoordPointer(1, GL_FLOAT, 0, texcoords_.data());
  gl_.glDrawElements(GL_TRIANGLES, GLsizei(indices.size()), GL_UNSIGNED_INT, indices.data());
  gl_.glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  gl_.glDisableClientState(GL_VERTEX_ARRAY);
  gl_.glDisable(GL_TEXTURE_1D);
}

void Canvas::colormap_rect(const Rect& r, Colormap map) {
  const Rect q = snapped(r);
  scalar_triangles({{q.x0, q.y1}, {q.x1, q.y1}, {q.x1, q.y0}, {q.x0, q.y0}}, {0, 0, 1, 1},
                   {0, 1, 2, 0, 2, 3}, map);
}

}  // namespace fsi::render::detail
