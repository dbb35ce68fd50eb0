#pragma once
// Framed axes shared by field frames and plots: a linear or logarithmic map from data
// to logical pixels, tick marks with labels outside the frame, an optional light grid.
#include <string>
#include <vector>

#include "canvas.hpp"

namespace fsi::render::detail {

/// Maps data values [lo, hi] onto pixel positions [p_lo, p_hi] (p_hi < p_lo for a y axis
/// pointing up).
struct AxisMap {
  double lo = 0, hi = 1;
  double p_lo = 0, p_hi = 1;
  bool log = false;
  float operator()(double v) const;
};

/// Ticks of one axis: positions in data units and their labels.
struct AxisTicks {
  std::vector<double> values;
  std::vector<std::string> labels;
};

/// Nice linear ticks (or decades for log) for an axis `length_px` long, about one per
/// `spacing_px` (pass x_tick_spacing / y_tick_spacing).
AxisTicks make_ticks(const AxisMap& map, float length_px, float spacing_px);

/// Tick spacing that keeps labels apart: a horizontal axis needs room for a label's
/// width, a vertical one only for its height [logical px].
inline float x_tick_spacing(float text_scale) { return 70.0f * text_scale; }
inline float y_tick_spacing(float text_scale) { return 35.0f * text_scale; }

/// Text size for a picture of `height` px, unless `requested` > 0: 1 at 240 px, ~2.5 at
/// 720 px, in steps of 0.5 so font strokes fall on whole supersampled pixels.
float auto_text_scale(int height, double requested);

/// Ink colours and sizes common to every figure.
inline constexpr Rgba ink{20, 20, 20, 255};
inline constexpr Rgba grid_ink{225, 225, 225, 255};

/// Widest label [logical px].
float max_label_width(const AxisTicks& ticks, float text_scale);

/// Light grid lines across `area` at the ticks: vertical lines for an x axis.
void draw_grid(Canvas& c, const Rect& area, const AxisMap& map, const AxisTicks& ticks,
               float text_scale, bool vertical_lines);

/// Which edge of a rectangle carries the ticks; marks point outwards, labels beyond them.
enum class Side { bottom, left, right };

void draw_ticks(Canvas& c, const Rect& area, const AxisMap& map, const AxisTicks& ticks,
                float text_scale, Side side);

}  // namespace fsi::render::detail
