// PNG through libpng's simplified API (png_image_*): it handles every colour type and
// bit depth on reading and reports errors through a message instead of longjmp.
#include "fsi/png.hpp"

#include <png.h>

#include <cstring>
#include <stdexcept>
#include <string>

namespace fsi::render {

void write_png(const std::filesystem::path& file, const Image& image, int compression_level) {
  if (image.empty() || image.rgba.size() != 4 * std::size_t(image.width) * image.height) {
    throw std::runtime_error(file.string() + ": cannot write an empty or inconsistent image");
  }
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  // The simplified writer has no compression setting, so use the classic API here;
  // level 3 is ~3x faster than the default 6 for a few percent larger frames.
  FILE* fp = std::fopen(file.c_str(), "wb");
  if (!fp) throw std::runtime_error(file.string() + ": cannot open for writing");
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    std::fclose(fp);
    throw std::runtime_error(file.string() + ": libpng failed while writing");
  }
  png_init_io(png, fp);
  png_set_compression_level(png, compression_level);
  png_set_IHDR(png, info, image.width, image.height, 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y) {
    png_write_row(png, image.rgba.data() + image.offset(0, y));
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  if (std::fclose(fp) != 0) throw std::runtime_error(file.string() + ": error closing file");
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
