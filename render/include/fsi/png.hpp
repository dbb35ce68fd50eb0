#pragma once
/// \file png.hpp
/// PNG files: 8-bit RGB (opaque images) or RGBA out, compressed with libdeflate; any
/// common PNG in through libpng (expanded to RGBA).
#include <cstdint>
#include <filesystem>
#include <vector>

#include "fsi/image.hpp"

namespace fsi::render {

/// Compression level of write_png/encode_png by default: fast enough to write a
/// 1280x720 frame per movie step (bench/render_bench.cpp: BM_FrameRenderAndPng).
/// Measured on such a field frame, one core: level 2 5.4 ms for 144 KB, 4 5.5-5.7 ms
/// for 116 KB, 6 7.1 ms for 99 KB (libpng with zlib's level 1, unfiltered: 8.8 ms for
/// 166 KB).
inline constexpr int png_fast_level = 4;

/// Writes an 8-bit PNG (top row first, as Image stores it): RGB when every pixel is
/// opaque, RGBA otherwise; rows unfiltered. Creates missing parent folders. Throws
/// std::runtime_error naming the file when it cannot write.
/// \param compression_level libdeflate level 0 (stored, fastest) .. 12 (smallest, slow).
void write_png(const std::filesystem::path& file, const Image& image,
               int compression_level = png_fast_level);

/// The bytes write_png would write.
std::vector<std::uint8_t> encode_png(const Image& image, int compression_level = png_fast_level);

/// Reads a PNG of any bit depth / colour type into 8-bit RGBA. Throws
/// std::runtime_error naming the file when it is missing or not a PNG.
Image read_png(const std::filesystem::path& file);

}  // namespace fsi::render
