#include "font.hpp"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_ADVANCES_H

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace fsi::render::detail {
namespace {

FT_Library lib(void* p) { return static_cast<FT_Library>(p); }
FT_Face face(void* p) { return static_cast<FT_Face>(p); }

std::vector<char32_t> make_charset() {
  std::vector<char32_t> cs;
  for (char32_t c = 0x20; c <= 0x7E; ++c) cs.push_back(c);  // ASCII
  for (char32_t c = 0xA0; c <= 0xFF; ++c) cs.push_back(c);  // Latin-1: degree, micro, ...
  for (char32_t c = 0x391; c <= 0x3C9; ++c) {               // Greek
    if (c != 0x3A2) cs.push_back(c);
  }
  for (char32_t c = 0x2070; c <= 0x2089; ++c) cs.push_back(c);  // super- and subscripts
  for (char32_t c : {0x2013, 0x2014, 0x2018, 0x2019, 0x201C, 0x201D, 0x2022, 0x2026,
                     0x2032, 0x2190, 0x2191, 0x2192, 0x2193, 0x2202, 0x2207, 0x2212,
                     0x221A, 0x221E, 0x2248, 0x2260, 0x2264, 0x2265, 0xFFFD}) {
    cs.push_back(c);
  }
  return cs;
}

}  // namespace

const std::vector<char32_t>& font_charset() {
  static const std::vector<char32_t> charset = make_charset();
  return charset;
}

std::u32string decode_utf8(std::string_view s) {
  std::u32string out;
  out.reserve(s.size());
  std::size_t i = 0;
  while (i < s.size()) {
    const unsigned char b = static_cast<unsigned char>(s[i]);
    const std::size_t extra = b < 0x80           ? 0
                              : (b >> 5) == 0x6  ? 1
                              : (b >> 4) == 0xE  ? 2
                              : (b >> 3) == 0x1E ? 3
                                                 : 9;  // 9: not a lead byte
    char32_t c = extra == 0 ? b : extra == 1 ? (b & 0x1F) : extra == 2 ? (b & 0x0F) : (b & 0x07);
    bool ok = extra <= 3 && i + extra < s.size();
    for (std::size_t k = 1; ok && k <= extra; ++k) {
      const unsigned char cb = static_cast<unsigned char>(s[i + k]);
      ok = (cb & 0xC0) == 0x80;
      c = (c << 6) | (cb & 0x3F);
    }
    if (!ok) {
      out.push_back(0xFFFD);
      ++i;
      continue;
    }
    out.push_back(c);
    i += extra + 1;
  }
  return out;
}

Font::Font(const std::filesystem::path& file) : file_(file) {
  FT_Library l = nullptr;
  if (FT_Init_FreeType(&l) != 0) throw std::runtime_error("FreeType: cannot initialize");
  library_ = l;
  FT_Face f = nullptr;
  if (!std::filesystem::exists(file) || FT_New_Face(l, file.c_str(), 0, &f) != 0) {
    FT_Done_FreeType(l);
    throw std::runtime_error("font " + file.string() +
                             ": missing or unreadable (Debian: apt-get install fonts-dejavu-core)");
  }
  face_ = f;
  const double em = f->units_per_EM;
  for (char32_t c : font_charset()) {
    const FT_UInt index = FT_Get_Char_Index(f, c);
    FT_Fixed advance = 0;
    if (index == 0 || FT_Get_Advance(f, index, FT_LOAD_NO_SCALE, &advance) != 0) continue;
    advances_[c] = float(double(advance) / em);
  }
  if (!advances_.count(U'?')) {
    FT_Done_Face(f);
    FT_Done_FreeType(l);
    throw std::runtime_error("font " + file.string() + ": has no glyph for '?'");
  }
  if (const FT_UInt h = FT_Get_Char_Index(f, U'H');
      h != 0 && FT_Load_Glyph(f, h, FT_LOAD_NO_SCALE) == 0) {
    cap_height_em_ = float(double(f->glyph->metrics.horiBearingY) / em);
  }
}

Font::~Font() {
  FT_Done_Face(face(face_));
  FT_Done_FreeType(lib(library_));
}

float Font::advance_em(char32_t c) const { return advances_.at(drawable(c)); }

float Font::width_em(std::u32string_view text) const {
  float w = 0;
  for (char32_t c : text) w += advance_em(c);
  return w;
}

GlyphBitmap Font::rasterize(char32_t c, int pixel_size) const {
  const std::lock_guard lock(mutex_);
  FT_Face f = face(face_);
  if (FT_Set_Pixel_Sizes(f, 0, FT_UInt(std::max(pixel_size, 1))) != 0) {
    throw std::runtime_error("font " + file_.string() + ": cannot set size " +
                             std::to_string(pixel_size) + " px");
  }
  const FT_UInt index = FT_Get_Char_Index(f, drawable(c));
  if (FT_Load_Glyph(f, index, FT_LOAD_TARGET_LIGHT | FT_LOAD_RENDER) != 0) {
    throw std::runtime_error("font " + file_.string() + ": cannot render U+" + std::to_string(c));
  }
  const FT_GlyphSlot g = f->glyph;
  const FT_Bitmap& b = g->bitmap;
  GlyphBitmap out;
  out.width = int(b.width);
  out.height = int(b.rows);
  out.left = g->bitmap_left;
  out.top = g->bitmap_top;
  out.coverage.resize(std::size_t(out.width) * out.height);
  if (b.pixel_mode != FT_PIXEL_MODE_GRAY && out.width * out.height > 0) {
    throw std::runtime_error("font " + file_.string() + ": not an 8-bit grey bitmap");
  }
  for (int y = 0; y < out.height; ++y) {
    std::memcpy(out.coverage.data() + std::size_t(y) * out.width, b.buffer + y * b.pitch,
                std::size_t(out.width));
  }
  return out;
}

const Font& default_font() {
  static const Font font{default_font_file};
  return font;
}

}  // namespace fsi::render::detail
