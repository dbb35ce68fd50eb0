#pragma once
/// \file movie_color_range.hpp
/// One colour range for every frame of a movie (a range that follows each frame makes
/// the colours flicker). The rule, in order:
///  1. the scenario's output.range_min < output.range_max: that range;
///  2. velocities (vx, vy: symmetric [-V, V]; vmag: [0, V]) from the speed a ball reaches
///     when it falls from its start to the lowest wall without drag, accelerated by
///     gravity against its own mass plus the displaced fluid's (a 2D cylinder's added mass):
///       V = 1.1 sqrt(|v0|^2 + 2 |g| h rho_s / (rho_s + rho_f)),
///     h = height of the ball's bottom above the lowest wall (domain bottom without walls);
///  3. umag: [0, 1.1 (h + r)] (the ball cannot move further than to the wall and a bit);
///  4. p: symmetric, the larger of rho_f V^2 and 2 max|p| of the first frame.
/// The range never clips a value that the run could plausibly reach; colours may stay a
/// little pale. Set output.range_min/max (or --set /output/range_max=...) to fix it.
#include <fsi/field_view.hpp>
#include <fsi/renderer.hpp>
#include <fsi/scenario.hpp>

namespace fsi::app {

/// The fixed range of `quantity` for a movie of `scenario`; `first` is the first frame.
render::ColorRange movie_color_range(const Scenario& scenario, render::Quantity quantity,
                                     const FieldView& first);

}  // namespace fsi::app
