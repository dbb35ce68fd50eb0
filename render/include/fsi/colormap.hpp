#pragma once
/// \file colormap.hpp
/// Perceptually uniform colour maps, tabulated at 256 entries. The renderer uploads a
/// table as a 1D texture and interpolates the *scalar* across each triangle, so the
/// colour of every pixel is looked up from its own value (no colour interpolation).
#include <array>
#include <cstdint>
#include <string_view>

namespace fsi::render {

enum class Colormap {
  viridis,    ///< sequential (dark blue -> yellow): magnitudes |v|, |u|
  cool_warm,  ///< diverging (blue -> white -> red, Moreland 2009): signed vx, vy, p
};

struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb8&, const Rgb8&) = default;
};

inline constexpr int colormap_size = 256;
using ColormapTable = std::array<Rgb8, colormap_size>;

/// The 256-entry table of a map; entry 0 is the low end, entry 255 the high end.
ColormapTable colormap_table(Colormap map);

/// Colour at t in [0, 1] (clamped), linearly interpolated between table entries.
Rgb8 colormap_color(Colormap map, double t);

/// True for maps whose centre means "zero" (their range should be symmetric).
bool is_diverging(Colormap map);

std::string_view colormap_name(Colormap map);

}  // namespace fsi::render
