#include <gtest/gtest.h>

#include <fsi/image_compare.hpp>

namespace fsi::render {
namespace {

Image gradient(int w, int h) {
  Image im = Image::filled(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      im.rgba[im.offset(x, y)] = std::uint8_t(x * 255 / w);
      im.rgba[im.offset(x, y) + 1] = std::uint8_t(y * 255 / h);
    }
  }
  return im;
}

TEST(ImageCompare, IdenticalImagesAreSame) {
  const Image a = gradient(64, 48);
  const ImageComparison r = compare_images(a, a);
  EXPECT_TRUE(r.same);
  EXPECT_EQ(r.bad_pixels, 0);
  EXPECT_EQ(r.max_difference, 0);
  EXPECT_EQ(r.total_pixels, 64 * 48);
  EXPECT_EQ(r.verdict.rfind("same", 0), 0u) << r.verdict;
}

TEST(ImageCompare, SmallNoiseWithinThresholdIsSame) {
  const Image a = gradient(64, 48);
  Image b = a;
  for (std::size_t i = 0; i < b.rgba.size(); i += 4) b.rgba[i + 2] -= (i / 4) % 9;  // 0..8
  EXPECT_TRUE(compare_images(a, b, 8, 0.0).same);
  EXPECT_FALSE(compare_images(a, b, 7, 0.0).same);
}

TEST(ImageCompare, DetectsAChangedRegion) {
  const Image a = gradient(100, 100);
  Image b = a;
  // A 10x10 square changed: 1% of the pixels, above the 0.5% default allowance.
  for (int y = 20; y < 30; ++y) {
    for (int x = 40; x < 50; ++x) b.rgba[b.offset(x, y)] ^= 0x80;
  }
  const ImageComparison r = compare_images(a, b);
  EXPECT_FALSE(r.same);
  EXPECT_EQ(r.bad_pixels, 100);
  EXPECT_DOUBLE_EQ(r.bad_fraction, 0.01);
  EXPECT_EQ(r.max_difference, 128);
  EXPECT_EQ(r.verdict.rfind("differ", 0), 0u) << r.verdict;
  // The diff marks exactly the changed square in red.
  EXPECT_GT(r.diff.rgba[r.diff.offset(45, 25)], 200);
  EXPECT_EQ(r.diff.rgba[r.diff.offset(45, 25) + 1], 0);
  EXPECT_EQ(r.diff.rgba[r.diff.offset(5, 5)], r.diff.rgba[r.diff.offset(5, 5) + 1]);
  // A looser allowance accepts it.
  EXPECT_TRUE(compare_images(a, b, 8, 0.02).same);
}

TEST(ImageCompare, SizeMismatchThrows) {
  EXPECT_THROW(compare_images(gradient(10, 10), gradient(10, 11)), std::invalid_argument);
}

}  // namespace
}  // namespace fsi::render
