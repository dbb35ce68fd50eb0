#include "fsi/colormap.hpp"

#include <algorithm>
#include <cmath>

#include "colormap_tables.hpp"

namespace fsi::render {

ColormapTable colormap_table(Colormap map) {
  switch (map) {
    case Colormap::viridis:
      return detail::viridis_table();
    case Colormap::cool_warm:
      return detail::cool_warm_table();
  }
  return detail::viridis_table();
}

Rgb8 colormap_color(Colormap map, double t) {
  const ColormapTable& table =
      map == Colormap::viridis ? detail::viridis_table() : detail::cool_warm_table();
  if (!std::isfinite(t)) t = 0.0;
  const double x = std::clamp(t, 0.0, 1.0) * (colormap_size - 1);
  const int i = std::min(int(x), colormap_size - 2);
  const double w = x - i;
  auto mix = [w](std::uint8_t a, std::uint8_t b) {
    return static_cast<std::uint8_t>(std::lround((1 - w) * a + w * b));
  };
  return {mix(table[i].r, table[i + 1].r), mix(table[i].g, table[i + 1].g),
          mix(table[i].b, table[i + 1].b)};
}

bool is_diverging(Colormap map) { return map == Colormap::cool_warm; }

std::string_view colormap_name(Colormap map) {
  return map == Colormap::viridis ? "viridis" : "cool-warm";
}

}  // namespace fsi::render
