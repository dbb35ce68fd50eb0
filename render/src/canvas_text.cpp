// Canvas text: quads textured from the glyph atlas of the size in framebuffer pixels,
// each glyph on whole pixels and sampled texel for texel (GL_NEAREST), so its
// antialiased FreeType bitmap arrives unchanged; the ink colour modulates the coverage.
#include <cmath>
#include <string>

#include "canvas.hpp"
#include "font.hpp"
#include "glyph_atlas.hpp"

namespace fsi::render::detail {
namespace {

// Font size [logical px per em] whose capitals are Canvas::text_height(scale) tall.
float em_size(float scale) { return Canvas::text_height(scale) / default_font().cap_height_em(); }

}  // namespace

float Canvas::text_width(std::string_view s, float scale) {
  return default_font().width_em(decode_utf8(s)) * em_size(scale);
}

unsigned Canvas::glyph_texture(int pixel_size) {
  unsigned& tex = glyph_textures_[pixel_size];
  if (tex) return tex;
  const GlyphAtlas& atlas = glyph_atlas(pixel_size);
  gl_.glGenTextures(1, &tex);
  gl_.glBindTexture(GL_TEXTURE_2D, tex);
  gl_.glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl_.glTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA8, atlas.width(), atlas.height(), 0, GL_ALPHA,
                   GL_UNSIGNED_BYTE, atlas.coverage().data());
  gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return tex;
}

void Canvas::text(std::string_view s, float x, float y, float scale, Rgba c, Align h, Align v,
                  bool vertical) {
  if (s.empty()) return;
  const Font& font = default_font();
  const std::u32string chars = decode_utf8(s);
  const float ss = float(supersample_), em = em_size(scale);
  const int pixel_size = std::max(1, int(std::lround(em * ss)));
  const GlyphAtlas& atlas = glyph_atlas(pixel_size);
  const unsigned tex = glyph_texture(pixel_size);

  auto offset = [](Align a, float size) {
    return a == Align::start ? 0.0f : a == Align::centre ? -size / 2 : -size;
  };
  const float width = font.width_em(chars) * em, cap = text_height(scale);
  // Text coordinates in framebuffer pixels: u along the text, w down across it, from the
  // anchor. Horizontal text: (u, w) = (x, y); vertical text is that turned 90 degrees
  // counter-clockwise, (x, y) = (w, -u).
  const float u0 = vertical ? -y * ss : x * ss, w0 = vertical ? x * ss : y * ss;
  const float pen0 = u0 + offset(h, width) * ss;
  const float baseline = std::round(w0 + (offset(v, cap) + cap) * ss);
  const float em_px = em * ss;
  auto corner = [&](float u, float w) {
    return vertical ? Vec2{w / ss, -u / ss} : Vec2{u / ss, w / ss};
  };
  const float tw = 1.0f / float(atlas.width()), th = 1.0f / float(atlas.height());
  vertices_.clear();
  texcoords_.clear();
  float pen = pen0;
  for (char32_t ch : chars) {
    const AtlasGlyph& g = atlas.glyph(font.drawable(ch));
    if (g.width > 0 && g.height > 0) {
      const float ua = std::round(pen) + float(g.left), ub = ua + float(g.width);
      const float wa = baseline - float(g.top), wb = wa + float(g.height);
      const float sa = float(g.x) * tw, sb = float(g.x + g.width) * tw;
      const float ta = float(g.y) * th, tb = float(g.y + g.height) * th;
      vertices_.insert(vertices_.end(), {corner(ua, wa), corner(ub, wa), corner(ub, wb),
                                         corner(ua, wa), corner(ub, wb), corner(ua, wb)});
      texcoords_.insert(texcoords_.end(), {sa, ta, sb, ta, sb, tb, sa, ta, sb, tb, sa, tb});
    }
    pen += font.advance_em(ch) * em_px;
  }
  if (vertices_.empty()) return;
  set_blending(true);
  gl_.glEnable(GL_TEXTURE_2D);
  gl_.glBindTexture(GL_TEXTURE_2D, tex);
  gl_.glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  gl_.glColor4ub(c.r, c.g, c.b, c.a);
  gl_.glEnableClientState(GL_VERTEX_ARRAY);
  gl_.glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  gl_.glVertexPointer(2, GL_FLOAT, sizeof(Vec2), vertices_.data());
  gl_.glTexCoordPointer(2, GL_FLOAT, 0, texcoords_.data());
  gl_.glDrawArrays(GL_TRIANGLES, 0, GLsizei(vertices_.size()));
  gl_.glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  gl_.glDisableClientState(GL_VERTEX_ARRAY);
  gl_.glDisable(GL_TEXTURE_2D);
}

}  // namespace fsi::render::detail
