#include "fsi/field_quantity.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fsi::render {

namespace {
constexpr Quantity all_quantities[] = {Quantity::vx, Quantity::vy, Quantity::vmag, Quantity::p,
                                       Quantity::umag};
}

QuantityInfo quantity_info(Quantity q) {
  switch (q) {
    case Quantity::vx:
      return {"vx", "v_x [m/s]", Colormap::cool_warm};
    case Quantity::vy:
      return {"vy", "v_y [m/s]", Colormap::cool_warm};
    case Quantity::vmag:
      return {"vmag", "|v| [m/s]", Colormap::viridis};
    case Quantity::p:
      return {"p", "p [Pa]", Colormap::cool_warm};
    case Quantity::umag:
      return {"umag", "|u| [m]", Colormap::viridis};
  }
  return {"?", "?", Colormap::viridis};
}

Quantity parse_quantity(std::string_view name) {
  std::string allowed;
  for (Quantity q : all_quantities) {
    if (quantity_info(q).name == name) return q;
    allowed += (allowed.empty() ? "" : ", ") + std::string(quantity_info(q).name);
  }
  throw std::invalid_argument("unknown field '" + std::string(name) + "', allowed: " + allowed);
}

std::vector<double> nodal_values(const FieldView& view, Quantity q) {
  const std::size_t n = view.nodes.size();
  std::vector<double> out(n, 0.0);
  auto at = [](const std::vector<double>& f, std::size_t i) { return i < f.size() ? f[i] : 0.0; };
  for (std::size_t i = 0; i < n; ++i) {
    switch (q) {
      case Quantity::vx:
        out[i] = at(view.vx, i);
        break;
      case Quantity::vy:
        out[i] = at(view.vy, i);
        break;
      case Quantity::vmag:
        out[i] = std::hypot(at(view.vx, i), at(view.vy, i));
        break;
      case Quantity::p:
        out[i] = at(view.p, i);
        break;
      case Quantity::umag:
        out[i] = std::hypot(at(view.ux, i), at(view.uy, i));
        break;
    }
  }
  return out;
}

ColorRange auto_range(const std::vector<double>& values, Colormap map) {
  double lo = INFINITY, hi = -INFINITY;
  for (double v : values) {
    if (std::isfinite(v)) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  if (lo > hi) return is_diverging(map) ? ColorRange{-1, 1} : ColorRange{0, 1};
  if (is_diverging(map)) {
    const double m = std::max(std::abs(lo), std::abs(hi));
    return m > 0 ? ColorRange{-m, m} : ColorRange{-1, 1};
  }
  if (lo >= 0) lo = 0;  // magnitudes start at zero
  if (hi - lo <= 0) {
    if (hi == 0) return {0, 1};
    const double pad = 0.1 * std::abs(hi);  // a negative constant
    return {lo - pad, hi + pad};
  }
  return {lo, hi};
}

ColorRange auto_range(const FieldView& view, Quantity q) {
  return auto_range(nodal_values(view, q), quantity_info(q).colormap);
}

ColorRange merge(const ColorRange& a, const ColorRange& b) {
  return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
}

}  // namespace fsi::render
