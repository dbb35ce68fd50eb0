#pragma once
/// \file png.hpp
/// PNG files through libpng: 8-bit RGBA out, any common PNG in (expanded to RGBA).
#include <filesystem>

#include "fsi/image.hpp"

namespace fsi::render {

/// Writes an 8-bit RGBA PNG (top row first, as Image stores it). Creates missing
/// parent folders. Throws std::runtime_error naming the file when it cannot write.
/// \param compression_level zlib level 0 (fastest, large) .. 9 (smallest, slow).
void write_png(const std::filesystem::path& file, const Image& image, int compression_level = 3);

/// Reads a PNG of any bit depth / colour type into 8-bit RGBA. Throws
/// std::runtime_error naming the file when it is missing or not a PNG.
Image read_png(const std::filesystem::path& file);

}  // namespace fsi::render
