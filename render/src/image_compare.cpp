#include "fsi/image_compare.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace fsi::render {

ImageComparison compare_images(const Image& expected, const Image& actual, int threshold,
                               double max_bad_fraction) {
  if (expected.width != actual.width || expected.height != actual.height) {
    throw std::invalid_argument("image sizes differ: expected " + std::to_string(expected.width) +
                                "x" + std::to_string(expected.height) + ", actual " +
                                std::to_string(actual.width) + "x" + std::to_string(actual.height));
  }
  const std::size_t n = std::size_t(expected.width) * expected.height;
  if (expected.rgba.size() != 4 * n || actual.rgba.size() != 4 * n) {
    throw std::invalid_argument("image buffer does not match its size");
  }
  ImageComparison r;
  r.total_pixels = long(n);
  r.diff = Image{expected.width, expected.height, std::vector<std::uint8_t>(4 * n)};
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* e = &expected.rgba[4 * i];
    const std::uint8_t* a = &actual.rgba[4 * i];
    int d = 0;
    for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(e[c]) - int(a[c])));
    r.max_difference = std::max(r.max_difference, d);
    std::uint8_t* o = &r.diff.rgba[4 * i];
    if (d > threshold) {
      ++r.bad_pixels;
      const int red = std::min(255, 128 + d);
      o[0] = std::uint8_t(red), o[1] = 0, o[2] = 0;
    } else {
      // Luminance faded towards white keeps the picture recognisable under the red.
      const int lum = (299 * e[0] + 587 * e[1] + 114 * e[2]) / 1000;
      o[0] = o[1] = o[2] = std::uint8_t(200 + lum * 55 / 255);
    }
    o[3] = 255;
  }
  r.bad_fraction = n ? double(r.bad_pixels) / double(n) : 0.0;
  r.same = r.bad_fraction <= max_bad_fraction;
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "%s: %.3f%% of pixels differ by > %d/255 (%ld of %ld, max %d; "
                "allowed %.3f%%)",
                r.same ? "same" : "differ", 100.0 * r.bad_fraction, threshold, r.bad_pixels,
                r.total_pixels, r.max_difference, 100.0 * max_bad_fraction);
  r.verdict = buf;
  return r;
}

}  // namespace fsi::render
