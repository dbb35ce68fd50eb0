#pragma once
/// \file fluid_element_jacobian.hpp
/// The Jacobian of a fluid sub-element's residual (forms/fsi_element.hpp), derived by hand.
///
/// Why: the automatic differentiation with Dual<20> (every local unknown carried through
/// every operation) was 30 % of the run time of Example 1's fall (`perf record` of
/// `fsi-bench-run assets/scenarios/ball_drop.json --end-time 0.2`), and most sub-elements
/// are fluid ones, whose residual is at most quadratic in v and p and linear in u with
/// no coupling from u at all: the derivatives have a short closed form. Solid
/// sub-elements (St. Venant-Kirchhoff through F = I - grad u) and fluid sub-elements on an
/// open boundary (the backflow term) keep the automatic differentiation.
///
/// tests/unit/fluid_element_jacobian_test.cpp checks it against the Dual<20> Jacobian to
/// round-off on quads and triangles, with and without the cavitation floor.
#include <array>

#include "forms/fsi_element.hpp"

namespace fsi::forms {

/// Row l, column j: d r_l / d x_j, l and j the local indices 5 a + field.
using ElementMatrix = std::array<std::array<double, kMaxLocal>, kMaxLocal>;

/// True where fluid_element_jacobian applies: a fluid sub-element with no open side.
inline bool has_hand_jacobian(const ElementInput& in) {
  return in.element->phase != Phase::solid && in.num_open_sides == 0;
}

/// The element Jacobian at x (only has_hand_jacobian(in) elements); the first
/// 5 vertices rows and columns of k are written, the rest left as they are.
void fluid_element_jacobian(const ElementInput& in, const FsiCoefficients& c,
                            const std::array<double, kMaxLocal>& x, ElementMatrix& k);

}  // namespace fsi::forms
