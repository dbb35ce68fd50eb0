// The cool-warm diverging map, generated (not copied) with the construction of
// K. Moreland, "Diverging Color Maps for Scientific Visualization" (ISVC 2009):
// interpolate between a blue and a red end in the polar Msh form of CIELAB, through
// an unsaturated white of lightness-magnitude 88, so lightness rises linearly to the
// centre and falls again. Zero therefore reads as white and both signs are equally salient.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "colormap_tables.hpp"

namespace fsi::render::detail {
namespace {

struct Msh {
  double m, s, h;
};

// D65 reference white in XYZ.
constexpr double white_x = 0.95047, white_y = 1.0, white_z = 1.08883;

double srgb_to_linear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
double linear_to_srgb(double c) {
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}
double lab_f(double t) { return t > 0.008856 ? std::cbrt(t) : 7.787 * t + 16.0 / 116.0; }
double lab_f_inverse(double f) {
  const double t = f * f * f;
  return t > 0.008856 ? t : (f - 16.0 / 116.0) / 7.787;
}

Msh msh_from_srgb8(int r8, int g8, int b8) {
  const double r = srgb_to_linear(r8 / 255.0), g = srgb_to_linear(g8 / 255.0),
               b = srgb_to_linear(b8 / 255.0);
  const double x = 0.4124 * r + 0.3576 * g + 0.1805 * b;
  const double y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  const double z = 0.0193 * r + 0.1192 * g + 0.9505 * b;
  const double fx = lab_f(x / white_x), fy = lab_f(y / white_y), fz = lab_f(z / white_z);
  const double l = 116.0 * fy - 16.0, a = 500.0 * (fx - fy), bb = 200.0 * (fy - fz);
  const double m = std::sqrt(l * l + a * a + bb * bb);
  return {m, std::acos(l / m), std::atan2(bb, a)};
}

Rgb8 srgb8_from_msh(const Msh& c) {
  const double l = c.m * std::cos(c.s), a = c.m * std::sin(c.s) * std::cos(c.h),
               bb = c.m * std::sin(c.s) * std::sin(c.h);
  const double fy = (l + 16.0) / 116.0, fx = fy + a / 500.0, fz = fy - bb / 200.0;
  const double x = white_x * lab_f_inverse(fx), y = white_y * lab_f_inverse(fy),
               z = white_z * lab_f_inverse(fz);
  const double lin[3] = {3.2406 * x - 1.5372 * y - 0.4986 * z,
                         -0.9689 * x + 1.8758 * y + 0.0415 * z,
                         0.0557 * x - 0.2040 * y + 1.0570 * z};
  std::uint8_t out[3];
  for (int k = 0; k < 3; ++k) {
    const double v = std::clamp(linear_to_srgb(std::clamp(lin[k], 0.0, 1.0)), 0.0, 1.0);
    out[k] = static_cast<std::uint8_t>(std::lround(255.0 * v));
  }
  return {out[0], out[1], out[2]};
}

// Moreland's hue spin: when one end is unsaturated (white), give it the hue of the
// saturated end, twisted so the path does not look muddy near the centre.
double adjust_hue(const Msh& saturated, double unsaturated_m) {
  if (saturated.m >= unsaturated_m) return saturated.h;
  const double spin = saturated.s *
                      std::sqrt(unsaturated_m * unsaturated_m - saturated.m * saturated.m) /
                      (saturated.m * std::sin(saturated.s));
  return saturated.h > -std::numbers::pi / 3.0 ? saturated.h + spin : saturated.h - spin;
}

Msh interpolate(Msh a, Msh b, double t) {
  constexpr double unsaturated = 0.05;
  if (a.s > unsaturated && b.s > unsaturated && std::abs(a.h - b.h) > std::numbers::pi / 3) {
    // Distinct hues: go through white at the centre.
    const double m_mid = std::max({a.m, b.m, 88.0});
    if (t < 0.5) {
      b = {m_mid, 0.0, 0.0};
      t = 2.0 * t;
    } else {
      a = {m_mid, 0.0, 0.0};
      t = 2.0 * t - 1.0;
    }
  }
  if (a.s < unsaturated && b.s > unsaturated) a.h = adjust_hue(b, a.m);
  if (b.s < unsaturated && a.s > unsaturated) b.h = adjust_hue(a, b.m);
  return {(1 - t) * a.m + t * b.m, (1 - t) * a.s + t * b.s, (1 - t) * a.h + t * b.h};
}

ColormapTable make_cool_warm() {
  const Msh blue = msh_from_srgb8(59, 76, 192);
  const Msh red = msh_from_srgb8(180, 4, 38);
  ColormapTable table;
  for (int i = 0; i < colormap_size; ++i) {
    table[i] = srgb8_from_msh(interpolate(blue, red, i / double(colormap_size - 1)));
  }
  return table;
}

}  // namespace

const ColormapTable& cool_warm_table() {
  // Computed once on first use; immutable afterwards (thread-safe static init).
  static const ColormapTable table = make_cool_warm();
  return table;
}

}  // namespace fsi::render::detail
