// PNG writing with libdeflate (whole-buffer DEFLATE: on a 1280x720 field frame 1.6x as
// fast as libpng with zlib level 1, for a smaller file; numbers in png.hpp), reading
// through libpng's simplified API (png_image_*), which handles every colour type and
// bit depth.
#include "fsi/png.hpp"

#include <libdeflate.h>
#include <png.h>

#include <array>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

namespace fsi::render {
namespace {

bool opaque(const Image& image) {
  const std::uint8_t* p = image.rgba.data();
  const std::size_t n = image.rgba.size();
  unsigned all = 255;
  for (std::size_t i = 3; i < n; i += 4) all &= p[i];
  return all == 255;
}

void check_image(const Image& image, const std::string& what) {
  if (image.empty() || image.rgba.size() != 4 * std::size_t(image.width) * image.height) {
    throw std::runtime_error(what + ": cannot write an empty or inconsistent image");
  }
}

std::uint8_t* put32(std::uint8_t* p, std::uint32_t v) {
  p[0] = std::uint8_t(v >> 24), p[1] = std::uint8_t(v >> 16), p[2] = std::uint8_t(v >> 8);
  p[3] = std::uint8_t(v);
  return p + 4;
}

// Writes a chunk's length, type and CRC around its `size` data bytes, which are
// already at chunk + 8. Returns the end of the chunk.
std::uint8_t* close_chunk(std::uint8_t* chunk, std::size_t size, const char type[4]) {
  put32(chunk, std::uint32_t(size));
  std::memcpy(chunk + 4, type, 4);
  return put32(chunk + 8 + size, std::uint32_t(libdeflate_crc32(0, chunk + 4, size + 4)));
}

struct CompressorDeleter {
  void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};

// Per thread: one compressor per level and the scratch rows, kept between frames so a
// movie allocates nothing per picture once they have grown.
struct Scratch {
  std::array<std::unique_ptr<libdeflate_compressor, CompressorDeleter>, 13> compressors;
  std::vector<std::uint8_t> raw;   // filter byte + pixels, per row
  std::vector<std::uint8_t> file;  // the PNG write_png writes
};

Scratch& scratch() {
  thread_local Scratch s;
  return s;
}

// The PNG of `image` into the first bytes of `out` (grown when needed, never shrunk, so
// a reused buffer is not cleared again per picture); returns their number.
std::size_t encode(const Image& image, int compression_level, std::vector<std::uint8_t>& out) {
  const int level = compression_level < 0 ? 0 : compression_level > 12 ? 12 : compression_level;
  Scratch& s = scratch();
  auto& compressor = s.compressors[std::size_t(level)];
  if (!compressor) compressor.reset(libdeflate_alloc_compressor(level));
  if (!compressor) throw std::runtime_error("encode_png: libdeflate_alloc_compressor failed");

  // Rows with filter type 0 (none): on a 1280x720 field frame at level 4 the Sub and Up
  // filters made the file larger (130 and 129 KB against 116 KB) and slower to write.
  const bool rgb = opaque(image);
  const std::size_t channels = rgb ? 3 : 4, w = std::size_t(image.width);
  const std::size_t row = 1 + channels * w;
  // One spare byte: the RGB copy below writes 4 bytes per 3-byte pixel.
  if (s.raw.size() < row * std::size_t(image.height) + 1) {
    s.raw.resize(row * std::size_t(image.height) + 1);
  }
  for (int y = 0; y < image.height; ++y) {
    std::uint8_t* d = s.raw.data() + row * std::size_t(y);
    const std::uint8_t* p = image.rgba.data() + image.offset(0, y);
    *d++ = 0;
    if (rgb) {
      // Whole pixels copied (4 bytes), each overwriting the alpha of the one before; the
      // last one spills into the next row's filter byte, written after it.
      for (std::size_t x = 0; x < w; ++x, d += 3, p += 4) std::memcpy(d, p, 4);
    } else {
      std::memcpy(d, p, 4 * w);
    }
  }
  const std::size_t raw_size = row * std::size_t(image.height);
  const std::size_t bound = libdeflate_zlib_compress_bound(compressor.get(), raw_size);
  if (out.size() < 8 + 25 + 12 + bound + 12) out.resize(8 + 25 + 12 + bound + 12);
  static constexpr std::uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  std::uint8_t* p = out.data();
  std::memcpy(p, signature, 8);
  p += 8;
  std::uint8_t* q = put32(put32(p + 8, std::uint32_t(image.width)), std::uint32_t(image.height));
  const std::uint8_t header[5] = {8, std::uint8_t(rgb ? 2 : 6), 0, 0, 0};  // depth, colour type
  std::memcpy(q, header, 5);
  p = close_chunk(p, 13, "IHDR");
  const std::size_t packed =
      libdeflate_zlib_compress(compressor.get(), s.raw.data(), raw_size, p + 8, bound);
  if (packed == 0) throw std::runtime_error("encode_png: libdeflate could not compress");
  p = close_chunk(p, packed, "IDAT");
  p = close_chunk(p, 0, "IEND");
  return std::size_t(p - out.data());
}

}  // namespace

std::vector<std::uint8_t> encode_png(const Image& image, int compression_level) {
  check_image(image, "encode_png");
  std::vector<std::uint8_t> out;
  out.resize(encode(image, compression_level, out));
  return out;
}

void write_png(const std::filesystem::path& file, const Image& image, int compression_level) {
  check_image(image, file.string());
  std::vector<std::uint8_t>& bytes = scratch().file;
  const std::size_t size = encode(image, compression_level, bytes);
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  std::FILE* fp = std::fopen(file.c_str(), "wb");
  if (!fp) throw std::runtime_error(file.string() + ": cannot open for writing");
  const bool written = std::fwrite(bytes.data(), 1, size, fp) == size;
  if (std::fclose(fp) != 0 || !written) {
    throw std::runtime_error(file.string() + ": error writing the file");
  }
}

Image read_png(const std::filesystem::path& file) {
  png_image pi;
  std::memset(&pi, 0, sizeof pi);
  pi.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&pi, file.c_str())) {
    const std::string why = pi.message;
    png_image_free(&pi);
    throw std::runtime_error(file.string() + ": cannot read PNG (" + why + ")");
  }
  pi.format = PNG_FORMAT_RGBA;
  Image image{int(pi.width), int(pi.height), {}};
  image.rgba.resize(PNG_IMAGE_SIZE(pi));
  if (!png_image_finish_read(&pi, nullptr, image.rgba.data(), 0, nullptr)) {
    const std::string why = pi.message;
    png_image_free(&pi);
    throw std::runtime_error(file.string() + ": cannot decode PNG (" + why + ")");
  }
  return image;
}

}  // namespace fsi::render
