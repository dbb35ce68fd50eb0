// The movie's colour range: an a-priori bound from the scenario (see the header).
#include "movie_color_range.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fsi::app {
namespace {

/// Height of the body's lowest point above the lowest wall point [m] (walls absent:
/// the bottom of the domain).
double fall_height(const Scenario& s, const BodySpec& body, const FieldView& view) {
  double floor_y = std::numeric_limits<double>::infinity();
  for (const Segment2& w : s.walls) floor_y = std::min({floor_y, w.a.y, w.b.y});
  if (!std::isfinite(floor_y)) floor_y = view.domain_min.y;
  return std::max(0.0, body.center_m.y - body_reach(body) - floor_y);
}

}  // namespace

render::ColorRange movie_color_range(const Scenario& s, render::Quantity q,
                                     const FieldView& first) {
  if (s.output.range_min < s.output.range_max) return {s.output.range_min, s.output.range_max};
  constexpr double kMargin = 1.1;
  const double g = std::hypot(s.gravity_mps2.x, s.gravity_mps2.y);
  // The fastest of the bodies (several: each bound on its own).
  double v = 1e-6, h = 0.0, reach = 0.0;
  for (const BodySpec& body : scene_bodies(s)) {
    const double hb = fall_height(s, body, first);
    const double v0 = std::hypot(body.initial_velocity_mps.x, body.initial_velocity_mps.y);
    const double rho_s = body_solid(s, body).density_kgpm3;
    const double mass_share = rho_s / (rho_s + s.fluid.density_kgpm3);
    v = std::max(v, kMargin * std::sqrt(v0 * v0 + 2 * g * hb * mass_share));
    h = std::max(h, hb);
    reach = std::max(reach, body_reach(body));
  }
  switch (q) {
    case render::Quantity::vx:
    case render::Quantity::vy:
      return {-v, v};
    case render::Quantity::vmag:
      return {0.0, v};
    case render::Quantity::umag:
      return {0.0, std::max(kMargin * (h + reach), 1e-6)};
    case render::Quantity::p: {
      const render::ColorRange seen = render::auto_range(first, q);
      const double m = std::max(s.fluid.density_kgpm3 * v * v,
                                2 * std::max(std::abs(seen.lo), std::abs(seen.hi)));
      return {-m, m};
    }
  }
  return render::auto_range(first, q);
}

}  // namespace fsi::app
