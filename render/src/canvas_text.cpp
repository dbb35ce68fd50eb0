// Canvas text through stb_easy_font: a public-domain stroke font that emits quads, so
// text needs no texture and scales to any size (blocky, but crisp and legible, and the
// canvas' supersampling smooths its edges).
#include <stb/stb_easy_font.h>

#include <string>

#include "canvas.hpp"

namespace fsi::render::detail {

float Canvas::text_width(std::string_view s, float scale) {
  std::string copy(s);  // the font takes a mutable char*
  // The font's width counts one column of trailing spacing; drop it for alignment.
  return s.empty() ? 0.0f : (stb_easy_font_width(copy.data()) - 1.0f) * scale;
}

void Canvas::text(std::string_view s, float x, float y, float scale, Rgba c, Align h, Align v,
                  bool vertical) {
  if (s.empty()) return;
  std::string copy(s);
  // The documented worst case is ~270 bytes per character.
  std::vector<char> buffer(300 * copy.size() + 1024);
  const int quads =
      stb_easy_font_print(0, 0, copy.data(), nullptr, buffer.data(), int(buffer.size()));
  const float w = text_width(s, scale), ht = text_height(scale);
  auto offset = [](Align a, float size) {
    return a == Align::start ? 0.0f : a == Align::centre ? -size / 2 : -size;
  };
  const float along = offset(h, w), across = offset(v, ht);
  std::vector<Vec2> verts;
  verts.reserve(std::size_t(quads) * 6);
  struct FontVertex {
    float x, y, z;
    unsigned char rgba[4];
  };
  const auto* fv = reinterpret_cast<const FontVertex*>(buffer.data());
  for (int q = 0; q < quads; ++q) {
    Vec2 corner[4];
    for (int k = 0; k < 4; ++k) {
      const float u = along + fv[4 * q + k].x * scale, w2 = across + fv[4 * q + k].y * scale;
      // Vertical text is the horizontal layout turned 90 degrees counter-clockwise.
      corner[k] = vertical ? Vec2{x + w2, y - u} : Vec2{x + u, y + w2};
    }
    verts.insert(verts.end(), {corner[0], corner[1], corner[2], corner[0], corner[2], corner[3]});
  }
  triangles(verts, c);
}

}  // namespace fsi::render::detail
