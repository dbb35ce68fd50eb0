#include <gtest/gtest.h>

#include <fsi/colormap.hpp>

namespace fsi::render {
namespace {

double luminance(Rgb8 c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

TEST(Colormap, ViridisEndsAndMiddle) {
  const ColormapTable t = colormap_table(Colormap::viridis);
  EXPECT_EQ(t.front(), (Rgb8{68, 1, 84}));    // dark violet
  EXPECT_EQ(t.back(), (Rgb8{253, 231, 37}));  // yellow
  EXPECT_EQ(t[128], (Rgb8{33, 145, 140}));    // teal
}

TEST(Colormap, ViridisLightnessIncreases) {
  // Perceptually uniform and sequential: luminance grows monotonically.
  const ColormapTable t = colormap_table(Colormap::viridis);
  for (int i = 1; i < colormap_size; ++i) {
    EXPECT_GT(luminance(t[i]), luminance(t[i - 1]) - 0.5) << "entry " << i;
  }
  EXPECT_GT(luminance(t.back()) - luminance(t.front()), 150);
}

TEST(Colormap, CoolWarmIsDivergingThroughGrey) {
  const ColormapTable t = colormap_table(Colormap::cool_warm);
  EXPECT_EQ(t.front(), (Rgb8{59, 76, 192}));  // Moreland's blue end
  EXPECT_EQ(t.back(), (Rgb8{180, 4, 38}));    // Moreland's red end
  // The centre is a light neutral grey (Moreland: 221, 221, 221).
  const Rgb8 mid = colormap_color(Colormap::cool_warm, 0.5);
  EXPECT_NEAR(mid.r, 221, 4);
  EXPECT_NEAR(mid.g, 221, 4);
  EXPECT_NEAR(mid.b, 221, 4);
  // Lightness rises to the centre and falls after it, symmetric in both halves.
  for (int i = 1; i < colormap_size / 2; ++i) {
    EXPECT_GE(luminance(t[i]) + 0.5, luminance(t[i - 1])) << "entry " << i;
    EXPECT_GE(luminance(t[colormap_size - 1 - i]) + 0.5, luminance(t[colormap_size - i]))
        << "entry " << colormap_size - 1 - i;
  }
  EXPECT_TRUE(t[40].b > t[40].r);    // cool side is blue
  EXPECT_TRUE(t[215].r > t[215].b);  // warm side is red
  EXPECT_TRUE(is_diverging(Colormap::cool_warm));
  EXPECT_FALSE(is_diverging(Colormap::viridis));
}

TEST(Colormap, LookupClampsAndInterpolates) {
  const ColormapTable t = colormap_table(Colormap::viridis);
  EXPECT_EQ(colormap_color(Colormap::viridis, -3.0), t.front());
  EXPECT_EQ(colormap_color(Colormap::viridis, 7.0), t.back());
  EXPECT_EQ(colormap_color(Colormap::viridis, 1.0), t.back());
  EXPECT_EQ(colormap_color(Colormap::viridis, 0.0), t.front());
  // Halfway between entries 0 and 1.
  const Rgb8 h = colormap_color(Colormap::viridis, 0.5 / (colormap_size - 1));
  EXPECT_NEAR(h.g, (t[0].g + t[1].g) / 2.0, 1.0);
}

}  // namespace
}  // namespace fsi::render
