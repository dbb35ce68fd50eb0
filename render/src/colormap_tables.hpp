#pragma once
// The tabulated colour maps behind colormap_table(): one source file each.
#include "fsi/colormap.hpp"

namespace fsi::render::detail {

const ColormapTable& viridis_table();
const ColormapTable& cool_warm_table();

}  // namespace fsi::render::detail
