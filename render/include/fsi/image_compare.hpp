#pragma once
/// \file image_compare.hpp
/// Tolerant pixel comparison for image regression tests: software rasterizers differ
/// in the last bit between versions, so a test asks "how many pixels are clearly off?"
/// rather than "is every byte equal?".
#include <string>

#include "fsi/image.hpp"

namespace fsi::render {

struct ImageComparison {
  long bad_pixels = 0;  ///< pixels where some channel differs by more than the threshold
  long total_pixels = 0;
  double bad_fraction = 0;  ///< bad_pixels / total_pixels, in [0, 1]
  int max_difference = 0;   ///< largest per-channel difference seen [0, 255]
  bool same = false;        ///< bad_fraction <= max_bad_fraction
  /// The expected image faded to light grey, with bad pixels in red (brighter = larger
  /// difference): where to look.
  Image diff;
  /// One line: "same: 0.012% of pixels differ by > 8/255 (max 12)" or "differ: ...".
  std::string verdict;
};

/// Compares decoded pixels (RGBA). A pixel is bad when any channel differs by more than
/// `threshold` (0..255). Throws std::invalid_argument when the sizes differ.
ImageComparison compare_images(const Image& expected, const Image& actual, int threshold = 8,
                               double max_bad_fraction = 0.005);

}  // namespace fsi::render
