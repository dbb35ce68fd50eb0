#include "glyph_atlas.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>

namespace fsi::render::detail {

GlyphAtlas::GlyphAtlas(const Font& font, int pixel_size) : pixel_size_(pixel_size) {
  const std::vector<char32_t>& charset = font_charset();
  std::vector<std::pair<char32_t, GlyphBitmap>> bitmaps;
  bitmaps.reserve(charset.size());
  for (char32_t c : charset) {
    if (font.drawable(c) == c) bitmaps.emplace_back(c, font.rasterize(c, pixel_size));
  }
  // Shelf packing, tallest first: rows of glyphs left to right, 1 px apart, in a strip
  // about as wide as the whole set would be square.
  std::vector<std::size_t> order(bitmaps.size());
  long area = 0;
  for (std::size_t i = 0; i < order.size(); ++i) {
    order[i] = i;
    area += long(bitmaps[i].second.width + 1) * (bitmaps[i].second.height + 1);
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return bitmaps[a].second.height > bitmaps[b].second.height;
  });
  int widest = 1;
  for (const auto& [c, b] : bitmaps) widest = std::max(widest, b.width + 2);
  width_ = std::max(widest, int(std::ceil(std::sqrt(double(area)) * 1.1)));
  int x = 1, y = 1, shelf = 0;
  for (std::size_t i : order) {
    const GlyphBitmap& b = bitmaps[i].second;
    if (x + b.width + 1 > width_) {
      x = 1;
      y += shelf + 1;
      shelf = 0;
    }
    glyphs_[bitmaps[i].first] = {x, y, b.width, b.height, b.left, b.top};
    x += b.width + 1;
    shelf = std::max(shelf, b.height);
  }
  height_ = y + shelf + 1;
  coverage_.assign(std::size_t(width_) * height_, 0);
  for (const auto& [c, b] : bitmaps) {
    const AtlasGlyph& g = glyphs_[c];
    for (int row = 0; row < b.height; ++row) {
      std::copy_n(b.coverage.data() + std::size_t(row) * b.width, b.width,
                  coverage_.data() + std::size_t(g.y + row) * width_ + g.x);
    }
  }
}

const AtlasGlyph& GlyphAtlas::glyph(char32_t c) const {
  const auto it = glyphs_.find(c);
  return it != glyphs_.end() ? it->second : glyphs_.at(U'?');
}

const GlyphAtlas& glyph_atlas(int pixel_size) {
  static std::mutex mutex;
  static std::map<int, std::unique_ptr<GlyphAtlas>> atlases;
  const std::lock_guard lock(mutex);
  auto& slot = atlases[pixel_size];
  if (!slot) slot = std::make_unique<GlyphAtlas>(default_font(), pixel_size);
  return *slot;
}

}  // namespace fsi::render::detail
