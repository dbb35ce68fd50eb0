// PNG writing through libpng's classic API (the simplified one has no compression
// settings), reading through its simplified API (png_image_*): it handles every colour
// type and bit depth and reports errors through a message instead of longjmp.
#include "fsi/png.hpp"

#include <png.h>
#include <zlib.h>

#include <cstdio>
#include <cstring>
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

// Encodes `image` through `write(data, size)`; false when libpng failed.
template <class Sink>
bool encode(const Image& image, int compression_level, Sink& sink) {
  // Everything that varies is settled before setjmp (a longjmp may clobber locals
  // changed after it).
  const int level = compression_level < 0 ? 0 : compression_level > 9 ? 9 : compression_level;
  const bool rgb = opaque(image);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(
      png, &sink,
      [](png_structp p, png_bytep data, png_size_t size) {
        static_cast<Sink*>(png_get_io_ptr(p))->write(data, size);
      },
      [](png_structp) {});
  png_set_compression_level(png, level);
  if (level <= 2) {
    // Measured on a 1280x720 field frame (bench/render_bench.cpp, one core): level 1
    // unfiltered takes a fraction of level 3 with adaptive filters, for ~1.5x the bytes.
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  }
  png_set_IHDR(png, info, image.width, image.height, 8, rgb ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_RGBA,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  // RGB out of RGBA rows: libpng drops the 4th byte of each pixel while writing.
  if (rgb) png_set_filler(png, 0, PNG_FILLER_AFTER);
  for (int y = 0; y < image.height; ++y) {
    png_write_row(png, image.rgba.data() + image.offset(0, y));
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

struct FileSink {
  std::FILE* fp;
  bool failed = false;
  void write(const std::uint8_t* data, std::size_t size) {
    failed |= std::fwrite(data, 1, size, fp) != size;
  }
};

struct MemorySink {
  std::vector<std::uint8_t>* out;
  void write(const std::uint8_t* data, std::size_t size) { out->insert(out->end(), data, data + size); }
};

}  // namespace

void write_png(const std::filesystem::path& file, const Image& image, int compression_level) {
  check_image(image, file.string());
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  std::FILE* fp = std::fopen(file.c_str(), "wb");
  if (!fp) throw std::runtime_error(file.string() + ": cannot open for writing");
  FileSink sink{fp};
  const bool ok = encode(image, compression_level, sink);
  const bool closed = std::fclose(fp) == 0;
  if (!ok) throw std::runtime_error(file.string() + ": libpng failed while writing");
  if (sink.failed || !closed) throw std::runtime_error(file.string() + ": error writing the file");
}

std::vector<std::uint8_t> encode_png(const Image& image, int compression_level) {
  check_image(image, "encode_png");
  std::vector<std::uint8_t> out;
  out.reserve(image.rgba.size() / 8);
  MemorySink sink{&out};
  if (!encode(image, compression_level, sink)) throw std::runtime_error("encode_png: libpng failed");
  return out;
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
