#include "axes.hpp"

#include <algorithm>
#include <cmath>

#include "fsi/axis_ticks.hpp"

namespace fsi::render::detail {

float AxisMap::operator()(double v) const {
  double t;
  if (log) {
    t = (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo));
  } else {
    t = (v - lo) / (hi - lo);
  }
  return float(p_lo + t * (p_hi - p_lo));
}

AxisTicks make_ticks(const AxisMap& map, float length_px, float spacing_px) {
  AxisTicks t;
  const int target = std::clamp(int(length_px / spacing_px), 2, 10);
  if (map.log) {
    t.values = log_ticks(map.lo, map.hi, target);
    for (double v : t.values) t.labels.push_back(format_tick(v, v));
  } else {
    t.values = nice_ticks(map.lo, map.hi, target);
    const double step = nice_step(map.lo, map.hi, target);
    for (double v : t.values) t.labels.push_back(format_tick(v, step));
  }
  return t;
}

float auto_text_scale(int height, double requested) {
  if (requested > 0) return float(requested);
  return std::max(1.0f, std::round(height / 300.0f * 2.0f) / 2.0f);
}

float max_label_width(const AxisTicks& ticks, float s) {
  float w = 0;
  for (const auto& l : ticks.labels) w = std::max(w, Canvas::text_width(l, s));
  return w;
}

void draw_x_axis(Canvas& c, const Rect& area, const AxisMap& map, const AxisTicks& ticks,
                 float s, bool grid) {
  const float ch = Canvas::text_height(s), tick = 0.5f * ch, lw = std::max(1.0f, 0.5f * s);
  std::vector<Vec2> marks, lines;
  for (std::size_t i = 0; i < ticks.values.size(); ++i) {
    const float x = map(ticks.values[i]);
    marks.insert(marks.end(), {{x, area.y1}, {x, area.y1 + tick}});
    if (grid) lines.insert(lines.end(), {{x, area.y0}, {x, area.y1}});
    c.text(ticks.labels[i], x, area.y1 + tick + 0.5f * ch, s, ink, Align::centre, Align::start);
  }
  if (grid) c.segments(lines, lw, grid_ink);
  c.segments(marks, lw, ink);
}

void draw_y_axis(Canvas& c, const Rect& area, const AxisMap& map, const AxisTicks& ticks,
                 float s, bool grid) {
  const float ch = Canvas::text_height(s), tick = 0.5f * ch, lw = std::max(1.0f, 0.5f * s);
  std::vector<Vec2> marks, lines;
  for (std::size_t i = 0; i < ticks.values.size(); ++i) {
    const float y = map(ticks.values[i]);
    marks.insert(marks.end(), {{area.x0 - tick, y}, {area.x0, y}});
    if (grid) lines.insert(lines.end(), {{area.x0, y}, {area.x1, y}});
    c.text(ticks.labels[i], area.x0 - tick - 0.5f * ch, y, s, ink, Align::end, Align::centre);
  }
  if (grid) c.segments(lines, lw, grid_ink);
  c.segments(marks, lw, ink);
}

}  // namespace fsi::render::detail
