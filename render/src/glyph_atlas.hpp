#pragma once
// Every glyph of font_charset() rasterized once at one pixel size and packed into one
// 8-bit coverage image (shelves, 1 px of paper between glyphs), for a GL texture.
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "font.hpp"

namespace fsi::render::detail {

/// Where a glyph sits in the atlas and how it is placed against the pen [px].
struct AtlasGlyph {
  int x = 0, y = 0;           ///< top-left corner in the atlas
  int width = 0, height = 0;  ///< of the bitmap (0 for a space)
  int left = 0, top = 0;      ///< as GlyphBitmap
};

class GlyphAtlas {
 public:
  GlyphAtlas(const Font& font, int pixel_size);

  int pixel_size() const { return pixel_size_; }
  int width() const { return width_; }    ///< [px]
  int height() const { return height_; }  ///< [px]
  /// width() * height() bytes, rows top first.
  const std::vector<std::uint8_t>& coverage() const { return coverage_; }
  /// The glyph drawn for `c` ('?' when the font has none).
  const AtlasGlyph& glyph(char32_t c) const;

 private:
  int pixel_size_ = 0, width_ = 0, height_ = 0;
  std::vector<std::uint8_t> coverage_;
  std::unordered_map<char32_t, AtlasGlyph> glyphs_;
};

/// The atlas of default_font() at `pixel_size`, made on first request and kept for the
/// life of the process (one per size; a field frame uses up to four: labels, title,
/// subscripts, the inset's tag). Thread-safe.
const GlyphAtlas& glyph_atlas(int pixel_size);

}  // namespace fsi::render::detail
