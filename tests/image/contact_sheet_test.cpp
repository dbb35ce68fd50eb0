#include <gtest/gtest.h>

#include <fsi/contact_sheet.hpp>
#include <stdexcept>

namespace fsi::render {
namespace {

TEST(ContactSheet, ShrinkAveragesAreas) {
  // Columns alternating black and white become mid grey at half the width; a 3 -> 2
  // shrink weights the middle column half to each side.
  Image im = Image::filled(4, 2, 255, 255, 255);
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 4; x += 2) {
      for (int c = 0; c < 3; ++c) im.rgba[im.offset(x, y) + c] = 0;
    }
  }
  const Image half = shrink(im, 2, 1);
  EXPECT_EQ(half.rgba[0], 128);
  EXPECT_EQ(half.rgba[4], 128);
  EXPECT_EQ(half.rgba[3], 255);
  Image three = Image::filled(3, 1, 0, 0, 0);
  three.rgba[three.offset(2, 0)] = 240;  // red channel of the last column
  const Image two = shrink(three, 2, 1);
  EXPECT_EQ(two.rgba[0], 0);    // 1 * col0 + 0.5 * col1, both 0
  EXPECT_EQ(two.rgba[4], 160);  // (0.5 * 0 + 1 * 240) / 1.5
  EXPECT_THROW(shrink(im, 0, 1), std::invalid_argument);
}

TEST(ContactSheet, PicksEvenlyWithBothEnds) {
  EXPECT_EQ(evenly_spaced(111, 6), (std::vector<std::size_t>{0, 22, 44, 66, 88, 110}));
  EXPECT_EQ(evenly_spaced(4, 6), (std::vector<std::size_t>{0, 1, 2, 3}));
  EXPECT_EQ(evenly_spaced(5, 1), (std::vector<std::size_t>{0}));
  EXPECT_TRUE(evenly_spaced(0, 6).empty());
}

TEST(ContactSheet, TilesInReadingOrderWithGaps) {
  std::vector<Image> frames;
  for (int i = 0; i < 6; ++i) frames.push_back(Image::filled(64, 36, std::uint8_t(40 * i), 0, 0));
  const Image sheet = contact_sheet(frames, 3, 32, 4);
  EXPECT_EQ(sheet.width, 4 + 3 * (32 + 4));
  EXPECT_EQ(sheet.height, 4 + 2 * (18 + 4));
  EXPECT_EQ(sheet.rgba[sheet.offset(0, 0)], 255);                  // gap: white
  EXPECT_EQ(sheet.rgba[sheet.offset(4 + 36 * 2 + 5, 4 + 5)], 80);  // 3rd tile, 1st row
  EXPECT_EQ(sheet.rgba[sheet.offset(4 + 5, 4 + 22 + 5)], 120);     // 4th tile, 2nd row
  frames[2] = Image::filled(10, 10);
  EXPECT_THROW(contact_sheet(frames, 3, 32), std::invalid_argument);
  EXPECT_THROW(contact_sheet({}, 3, 32), std::invalid_argument);
}

}  // namespace
}  // namespace fsi::render
