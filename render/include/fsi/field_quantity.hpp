#pragma once
/// \file field_quantity.hpp
/// The scalar quantities a frame can show, with their names, units and colour maps, and
/// their nodal values taken from a FieldView.
#include <fsi/field_view.hpp>
#include <string_view>
#include <vector>

#include "fsi/colormap.hpp"

namespace fsi::render {

enum class Quantity {
  vx,    ///< velocity x [m/s], signed
  vy,    ///< velocity y [m/s], signed
  vmag,  ///< velocity magnitude |v| [m/s]
  p,     ///< pressure [Pa], signed
  umag,  ///< displacement magnitude |u| [m]
};

struct QuantityInfo {
  std::string_view name;   ///< short name for files and command lines: "vx", "vmag", ...
  std::string_view label;  ///< colour bar label with unit: "v_y [m/s]"
  Colormap colormap;       ///< cool_warm for signed quantities, viridis for magnitudes
};

QuantityInfo quantity_info(Quantity q);

/// Parses a name as in QuantityInfo::name; throws std::invalid_argument listing the
/// allowed names otherwise.
Quantity parse_quantity(std::string_view name);

/// One value per node of `view` [unit of the quantity].
std::vector<double> nodal_values(const FieldView& view, Quantity q);

/// A colour range [lo, hi] in the quantity's unit.
struct ColorRange {
  double lo = 0.0;
  double hi = 1.0;
};

/// The range of the finite values: [0, max] for magnitudes, [-m, m] with m = max |value|
/// for signed quantities (so white means zero), never empty (a constant field gets a
/// unit-width or 10% range around its value).
ColorRange auto_range(const std::vector<double>& values, Colormap map);

/// auto_range over the nodal values of q.
ColorRange auto_range(const FieldView& view, Quantity q);

/// The smallest range containing both (to fix one range across the frames of a movie).
ColorRange merge(const ColorRange& a, const ColorRange& b);

}  // namespace fsi::render
