#pragma once
/// \file image.hpp
/// The picture type every part of fsi::render shares: the renderer makes one, the PNG
/// and video encoders consume one, the comparison reads two.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fsi::render {

/// An 8-bit RGBA image, rows top to bottom, pixels left to right (row-major,
/// 4 bytes per pixel, no padding), so rgba.size() == 4 * width * height.
struct Image {
  int width = 0;                   ///< [px]
  int height = 0;                  ///< [px]
  std::vector<std::uint8_t> rgba;  ///< 4 * width * height bytes, top row first

  /// A width x height image filled with one colour (opaque white by default).
  static Image filled(int width, int height, std::uint8_t r = 255, std::uint8_t g = 255,
                      std::uint8_t b = 255, std::uint8_t a = 255) {
    Image im{width, height, std::vector<std::uint8_t>(4 * std::size_t(width) * height)};
    for (std::size_t i = 0; i < im.rgba.size(); i += 4) {
      im.rgba[i] = r;
      im.rgba[i + 1] = g;
      im.rgba[i + 2] = b;
      im.rgba[i + 3] = a;
    }
    return im;
  }

  /// Byte offset of pixel (x, y), y counted from the top row.
  std::size_t offset(int x, int y) const { return 4 * (std::size_t(y) * width + x); }
  bool empty() const { return width <= 0 || height <= 0; }
};

}  // namespace fsi::render
