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
    // A short axis (a colour bar beside a small panel) asks for two ticks, and the nice
    // step for two can leave a single one inside (0 of [-430, 430] at step 500): ask
    // for more until two fit.
    int wanted = target;
    t.values = nice_ticks(map.lo, map.hi, wanted);
    while (t.values.size() < 2 && wanted < 8) t.values = nice_ticks(map.lo, map.hi, ++wanted);
    const double step = nice_step(map.lo, map.hi, wanted);
    for (double v : t.values) t.labels.push_back(format_tick(v, step));
  }
  // A typeset minus sign (U+2212, as wide as the plus sign) instead of the hyphen:
  // "-0.5" reads as "−0.5".
  for (std::string& l : t.labels) {
    for (std::size_t at = l.find('-'); at != std::string::npos; at = l.find('-', at + 3)) {
      l.replace(at, 1, "\u2212");
    }
  }
  // An axis shorter than two spacings (a thin strip of a letterboxed zoom) still gets two
  // or three nice ticks, whose labels would overlap: keep every 2nd, 4th, ... of them
  // until neighbours are half a spacing apart (one label at least).
  while (t.values.size() > 1 && std::abs(map(t.values[1]) - map(t.values[0])) < 0.5f * spacing_px) {
    AxisTicks kept;
    for (std::size_t i = 0; i < t.values.size(); i += 2) {
      kept.values.push_back(t.values[i]);
      kept.labels.push_back(t.labels[i]);
    }
    t = std::move(kept);
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

void draw_grid(Canvas& c, const Rect& area, const AxisMap& map, const AxisTicks& ticks, float s,
               bool vertical_lines) {
  std::vector<Vec2> lines;
  for (double v : ticks.values) {
    const float p = map(v);
    if (vertical_lines) {
      lines.insert(lines.end(), {{p, area.y0}, {p, area.y1}});
    } else {
      lines.insert(lines.end(), {{area.x0, p}, {area.x1, p}});
    }
  }
  c.segments(lines, std::max(1.0f, 0.5f * s), grid_ink);
}

void draw_ticks(Canvas& c, const Rect& area, const AxisMap& map, const AxisTicks& ticks, float s,
                Side side) {
  const float ch = Canvas::text_height(s), tick = 0.5f * ch, gap = tick + 0.5f * ch;
  std::vector<Vec2> marks;
  for (std::size_t i = 0; i < ticks.values.size(); ++i) {
    const float p = map(ticks.values[i]);
    const std::string& label = ticks.labels[i];
    switch (side) {
      case Side::bottom:
        marks.insert(marks.end(), {{p, area.y1}, {p, area.y1 + tick}});
        c.text(label, p, area.y1 + gap, s, ink, Align::centre, Align::start);
        break;
      case Side::left:
        marks.insert(marks.end(), {{area.x0 - tick, p}, {area.x0, p}});
        c.text(label, area.x0 - gap, p, s, ink, Align::end, Align::centre);
        break;
      case Side::right:
        marks.insert(marks.end(), {{area.x1, p}, {area.x1 + tick, p}});
        c.text(label, area.x1 + gap, p, s, ink, Align::start, Align::centre);
        break;
    }
  }
  c.segments(marks, std::max(1.0f, 0.5f * s), ink);
}

}  // namespace fsi::render::detail
