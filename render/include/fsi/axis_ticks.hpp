#pragma once
/// \file axis_ticks.hpp
/// "Nice" axis ticks (steps of 1, 2 or 5 times a power of ten) and their labels, shared
/// by the colour bar, the frame axes and the plots.
#include <string>
#include <vector>

namespace fsi::render {

/// Tick step for about `target` intervals over [lo, hi]: 1, 2 or 5 x 10^k.
double nice_step(double lo, double hi, int target = 5);

/// The multiples of nice_step() inside [lo, hi] (ends included within 1e-9 of a step).
std::vector<double> nice_ticks(double lo, double hi, int target = 5);

/// Ticks of a logarithmic axis over [lo, hi] (lo > 0): powers of ten (every n-th when
/// there are more than `target`), or 1-2-5 / 1..9 multiples when fewer than 3 decades fit.
std::vector<double> log_ticks(double lo, double hi, int target = 6);

/// A tick label with as many decimals as the step needs ("0.25", "-1.5", "0"), switching
/// to scientific notation ("2e-04", "1.5e+06") for very small or very large numbers.
std::string format_tick(double value, double step);

}  // namespace fsi::render
