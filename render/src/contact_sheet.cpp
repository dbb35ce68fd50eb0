#include "fsi/contact_sheet.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fsi::render {
namespace {

// Source pixels [lo, hi) with their weights covering output pixel i of n along an axis
// of `size` source pixels.
struct Span {
  int lo = 0, hi = 0;
  std::vector<double> weight;  // hi - lo entries, summing to 1
};

std::vector<Span> spans(int size, int n) {
  std::vector<Span> out(static_cast<std::size_t>(n));
  const double f = double(size) / n;
  for (int i = 0; i < n; ++i) {
    const double a = i * f, b = (i + 1) * f;
    Span& s = out[std::size_t(i)];
    s.lo = int(std::floor(a));
    s.hi = std::min(size, int(std::ceil(b)));
    for (int k = s.lo; k < s.hi; ++k) {
      s.weight.push_back((std::min(b, k + 1.0) - std::max(a, double(k))) / f);
    }
  }
  return out;
}

}  // namespace

Image shrink(const Image& image, int width, int height) {
  if (image.empty() || width < 1 || height < 1) {
    throw std::invalid_argument("shrink: empty image or target size below 1 px");
  }
  // Separable: rows first into doubles, then columns.
  const std::vector<Span> sx = spans(image.width, width), sy = spans(image.height, height);
  std::vector<double> rows(std::size_t(width) * image.height * 4);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < width; ++x) {
      const Span& s = sx[std::size_t(x)];
      double* d = &rows[(std::size_t(y) * width + x) * 4];
      for (int k = s.lo; k < s.hi; ++k) {
        const std::uint8_t* p = &image.rgba[image.offset(k, y)];
        for (int c = 0; c < 4; ++c) d[c] += s.weight[std::size_t(k - s.lo)] * p[c];
      }
    }
  }
  Image out = Image::filled(width, height);
  for (int y = 0; y < height; ++y) {
    const Span& s = sy[std::size_t(y)];
    for (int x = 0; x < width; ++x) {
      double v[4] = {0, 0, 0, 0};
      for (int k = s.lo; k < s.hi; ++k) {
        const double* r = &rows[(std::size_t(k) * width + x) * 4];
        for (int c = 0; c < 4; ++c) v[c] += s.weight[std::size_t(k - s.lo)] * r[c];
      }
      std::uint8_t* d = &out.rgba[out.offset(x, y)];
      for (int c = 0; c < 4; ++c) d[c] = std::uint8_t(std::clamp(std::lround(v[c]), 0L, 255L));
    }
  }
  return out;
}

std::vector<std::size_t> evenly_spaced(std::size_t count, std::size_t n) {
  std::vector<std::size_t> out;
  if (count == 0 || n == 0) return out;
  if (count <= n || n == 1) {
    for (std::size_t i = 0; i < std::min(count, n); ++i) out.push_back(i);
    return out;
  }
  for (std::size_t i = 0; i < n; ++i) {
    out.push_back(std::size_t(std::lround(double(i) * double(count - 1) / double(n - 1))));
  }
  return out;
}

Image contact_sheet(const std::vector<Image>& frames, int columns, int tile_width, int gap) {
  if (frames.empty() || columns < 1 || tile_width < 1 || gap < 0) {
    throw std::invalid_argument("contact_sheet: no frames, or columns / tile width below 1");
  }
  const Image& first = frames.front();
  for (const Image& f : frames) {
    if (f.width != first.width || f.height != first.height || f.empty()) {
      throw std::invalid_argument("contact_sheet: frames differ in size (" +
                                  std::to_string(f.width) + "x" + std::to_string(f.height) +
                                  " and " + std::to_string(first.width) + "x" +
                                  std::to_string(first.height) + ")");
    }
  }
  const int tile_height =
      std::max(1, int(std::lround(double(tile_width) * first.height / first.width)));
  const int cols = std::min<int>(columns, int(frames.size()));
  const int rows = (int(frames.size()) + cols - 1) / cols;
  Image sheet = Image::filled(gap + cols * (tile_width + gap), gap + rows * (tile_height + gap));
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const Image tile = shrink(frames[i], tile_width, tile_height);
    const int x0 = gap + int(i % std::size_t(cols)) * (tile_width + gap);
    const int y0 = gap + int(i / std::size_t(cols)) * (tile_height + gap);
    for (int y = 0; y < tile_height; ++y) {
      std::copy_n(&tile.rgba[tile.offset(0, y)], 4 * std::size_t(tile_width),
                  &sheet.rgba[sheet.offset(x0, y0 + y)]);
    }
  }
  return sheet;
}

}  // namespace fsi::render
