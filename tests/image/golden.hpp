#pragma once
// Golden-image checks for the renderer tests.
//
// A picture is compared with tests/golden/<name>.png by decoded pixels: the test fails
// when more than 0.5% of the pixels differ by more than 8/255 in some channel. On a
// failure, <build>/image-test-output/<name>.{actual,expected,diff}.png show what changed.
//
// To accept new pictures (after a deliberate change), regenerate the goldens:
//     FSI_UPDATE_GOLDENS=1 ctest --test-dir build -L image     (or tools/update-goldens)
// then look at them and commit tests/golden/.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fsi/image_compare.hpp>
#include <fsi/png.hpp>
#include <string>

namespace fsi::render::testing {

inline constexpr int golden_threshold = 8;  // per channel, of 255
inline constexpr double golden_max_bad_fraction = 0.005;

inline std::filesystem::path golden_path(const std::string& name) {
  return std::filesystem::path(FSI_SOURCE_DIR) / "tests" / "golden" / (name + ".png");
}

inline std::filesystem::path output_dir() {
  return std::filesystem::path(FSI_BINARY_DIR) / "image-test-output";
}

inline bool updating_goldens() {
  const char* v = std::getenv("FSI_UPDATE_GOLDENS");
  return v && std::string(v) == "1";
}

/// EXPECTs that `actual` matches the golden picture `name`.
inline void expect_matches_golden(const std::string& name, const Image& actual) {
  const auto golden = golden_path(name);
  if (updating_goldens()) {
    write_png(golden, actual, 12);  // smallest: goldens are kept in the repository
    std::printf("updated golden %s\n", golden.c_str());
    return;
  }
  if (!std::filesystem::exists(golden)) {
    write_png(output_dir() / (name + ".actual.png"), actual);
    ADD_FAILURE() << "no golden " << golden
                  << "; create it with FSI_UPDATE_GOLDENS=1 ctest -L image";
    return;
  }
  const Image expected = read_png(golden);
  if (expected.width != actual.width || expected.height != actual.height) {
    write_png(output_dir() / (name + ".actual.png"), actual);
    ADD_FAILURE() << name << ": size " << actual.width << "x" << actual.height << " but golden is "
                  << expected.width << "x" << expected.height;
    return;
  }
  const ImageComparison cmp =
      compare_images(expected, actual, golden_threshold, golden_max_bad_fraction);
  if (!cmp.same) {
    const auto dir = output_dir();
    write_png(dir / (name + ".actual.png"), actual);
    write_png(dir / (name + ".expected.png"), expected);
    write_png(dir / (name + ".diff.png"), cmp.diff);
    ADD_FAILURE() << name << ": " << cmp.verdict << "; see " << (dir / (name + ".*.png"));
  }
}

}  // namespace fsi::render::testing
