#include <gtest/gtest.h>

#include <filesystem>
#include <fsi/png.hpp>
#include <string>
#include <vector>

namespace fsi::render {
namespace {

std::filesystem::path scratch(const std::string& name) {
  return std::filesystem::path(FSI_BINARY_DIR) / "image-test-output" / name;
}

TEST(Png, RoundTripKeepsEveryByteAndTheOrientation) {
  Image im = Image::filled(7, 5, 10, 20, 30, 255);
  im.rgba[im.offset(0, 0)] = 255;      // top-left red
  im.rgba[im.offset(6, 4) + 2] = 200;  // bottom-right bluish
  im.rgba[im.offset(3, 2) + 3] = 128;  // half transparent
  const auto file = scratch("roundtrip.png");
  write_png(file, im);
  const Image back = read_png(file);
  EXPECT_EQ(back.width, 7);
  EXPECT_EQ(back.height, 5);
  EXPECT_EQ(back.rgba, im.rgba);
}

TEST(Png, OpaqueImagesAreWrittenAsRgbOthersAsRgba) {
  // IHDR's colour type sits at byte 25 (8 signature + 8 chunk head + 9 into the data).
  Image im = Image::filled(9, 4, 1, 2, 3, 255);
  const std::vector<std::uint8_t> rgb = encode_png(im);
  ASSERT_GT(rgb.size(), 33u);
  EXPECT_EQ(rgb[25], 2);  // truecolour
  im.rgba[im.offset(8, 3) + 3] = 254;
  EXPECT_EQ(encode_png(im)[25], 6);  // truecolour with alpha
  // The file holds exactly encode_png's bytes, and reading it gives the pixels back.
  const auto file = scratch("rgb.png");
  write_png(file, Image::filled(9, 4, 1, 2, 3, 255));
  EXPECT_EQ(std::filesystem::file_size(file), rgb.size());
  EXPECT_EQ(read_png(file).rgba, Image::filled(9, 4, 1, 2, 3, 255).rgba);
}

TEST(Png, EveryLevelRoundTrips) {
  Image im = Image::filled(31, 17);
  for (std::size_t i = 0; i < im.rgba.size(); ++i) {
    if (i % 4 != 3) im.rgba[i] = std::uint8_t((i * 37) ^ (i >> 5));
  }
  for (int level : {0, 1, 2, 6, 12}) {
    const auto file = scratch("level" + std::to_string(level) + ".png");
    write_png(file, im, level);
    EXPECT_EQ(read_png(file).rgba, im.rgba) << "level " << level;
  }
}

TEST(Png, MissingOrBadFilesThrowWithTheirName) {
  try {
    read_png(scratch("does-not-exist.png"));
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("does-not-exist.png"), std::string::npos) << e.what();
  }
  EXPECT_THROW(write_png(scratch("empty.png"), Image{}), std::runtime_error);
}

}  // namespace
}  // namespace fsi::render
