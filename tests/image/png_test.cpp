#include <gtest/gtest.h>

#include <filesystem>
#include <fsi/png.hpp>

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
