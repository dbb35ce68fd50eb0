// A line plot laid out like a paper figure: title on top, framed axes with a light
// grid, tick labels outside, axis labels (y rotated), legend in the upper right corner.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "axes.hpp"
#include "drawings.hpp"

namespace fsi::render::detail {
namespace {

// Okabe & Ito's colour-blind-safe palette (without its yellow, too light on white).
constexpr Rgba palette[] = {{0, 114, 178, 255},   {213, 94, 0, 255},  {0, 158, 115, 255},
                            {204, 121, 167, 255}, {230, 159, 0, 255}, {86, 180, 233, 255},
                            {0, 0, 0, 255}};

bool usable(double x, double y, bool log_y) {
  return std::isfinite(x) && std::isfinite(y) && (!log_y || y > 0);
}

struct Limits {
  double lo = INFINITY, hi = -INFINITY;
  void add(double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
};

// Data limits widened so the curves do not touch the frame, and never empty.
void finish_limits(Limits& l, bool log, double margin) {
  if (!(l.lo <= l.hi)) l = log ? Limits{1, 10} : Limits{0, 1};
  if (log) {
    double a = std::log10(l.lo), b = std::log10(l.hi);
    if (b - a < 1e-12) a -= 0.5, b += 0.5;
    const double m = margin * (b - a);
    l = {std::pow(10.0, a - m), std::pow(10.0, b + m)};
    return;
  }
  if (l.hi - l.lo <= 0) {
    const double pad = l.hi != 0 ? 0.1 * std::abs(l.hi) : 1.0;
    l = {l.lo - pad, l.hi + pad};
    return;
  }
  const double m = margin * (l.hi - l.lo);
  l = {l.lo - m, l.hi + m};
}

// The legend goes into the corner of the plot area that hides the fewest data points
// (checked in the order top right, top left, bottom right, bottom left).
void draw_legend(Canvas& c, const PlotSpec& spec, const Rect& area, float s,
                 const std::vector<Vec2>& data_points) {
  const float ch = Canvas::text_height(s), sample = 3.0f * ch, row = 2.0f * ch;
  float text_w = 0;
  int rows = 0;
  for (const auto& se : spec.series) {
    if (se.label.empty()) continue;
    text_w = std::max(text_w, Canvas::text_width(se.label, s));
    ++rows;
  }
  if (rows == 0) return;
  const float bw = sample + 3.0f * ch + text_w, bh = rows * row + ch;
  Rect box;
  long fewest = -1;
  for (const auto& [right, top] :
       {std::pair{true, true}, {false, true}, {true, false}, {false, false}}) {
    const float x0 = right ? area.x1 - ch - bw : area.x0 + ch;
    const float y0 = top ? area.y0 + ch : area.y1 - ch - bh;
    const Rect candidate{x0, y0, x0 + bw, y0 + bh};
    const long hidden = std::count_if(data_points.begin(), data_points.end(), [&](Vec2 p) {
      return p.x >= candidate.x0 && p.x <= candidate.x1 && p.y >= candidate.y0 &&
             p.y <= candidate.y1;
    });
    if (fewest < 0 || hidden < fewest) fewest = hidden, box = candidate;
  }
  c.fill_rect(box, {255, 255, 255, 235});
  c.stroke_rect(box, std::max(1.0f, 0.4f * s), {170, 170, 170, 255});
  float y = box.y0 + ch + row / 2;
  for (std::size_t i = 0; i < spec.series.size(); ++i) {
    if (spec.series[i].label.empty()) continue;
    const Rgba col = palette[i % std::size(palette)];
    c.polyline({{box.x0 + ch, y}, {box.x0 + ch + sample, y}}, float(spec.line_width), col);
    c.text(spec.series[i].label, box.x0 + 2.0f * ch + sample, y, s, ink, Align::start,
           Align::centre);
    y += row;
  }
}

}  // namespace

Image draw_plot(Canvas& c, const PlotSpec& spec) {
  Limits lx, ly;
  for (const auto& se : spec.series) {
    if (se.x.size() != se.y.size()) {
      throw std::invalid_argument("PlotSpec: series '" + se.label + "' has " +
                                  std::to_string(se.x.size()) + " x but " +
                                  std::to_string(se.y.size()) + " y values");
    }
    for (std::size_t i = 0; i < se.x.size(); ++i) {
      if (!usable(se.x[i], se.y[i], spec.log_y)) continue;
      lx.add(se.x[i]);
      // The y range covers what is shown: with fixed x limits (a zoom on the contact
      // interval), only the points between them.
      if ((spec.x_min && se.x[i] < *spec.x_min) || (spec.x_max && se.x[i] > *spec.x_max)) continue;
      ly.add(se.y[i]);
    }
  }
  finish_limits(lx, false, 0.0);  // time axes start and end at the data
  finish_limits(ly, spec.log_y, 0.05);
  if (spec.x_min) lx.lo = *spec.x_min;
  if (spec.x_max) lx.hi = *spec.x_max;
  if (spec.y_min) ly.lo = *spec.y_min;
  if (spec.y_max) ly.hi = *spec.y_max;
  if (!(lx.hi > lx.lo) || !(ly.hi > ly.lo) || (spec.log_y && !(ly.lo > 0))) {
    throw std::invalid_argument("PlotSpec: axis limits must satisfy min < max (and > 0 on log)");
  }

  c.begin(spec.width, spec.height, spec.supersample);
  const float s = auto_text_scale(spec.height, spec.text_scale), ch = Canvas::text_height(s);
  const float pad = 1.5f * ch;
  const float guess_h = spec.height * 0.7f;
  const AxisTicks yt_guess =
      make_ticks({ly.lo, ly.hi, guess_h, 0, spec.log_y}, guess_h, y_tick_spacing(s));
  const float left = pad + 2.0f * ch + max_label_width(yt_guess, s) + 1.5f * ch;
  const float top = pad + (spec.title.empty() ? 0.0f : 2.5f * ch);
  const float right = pad + 2.0f * ch;  // room for the last x tick label
  const float bottom = pad + 4.0f * ch;
  const Rect area{left, top, spec.width - right, spec.height - bottom};
  if (area.width() < 10 || area.height() < 10) {
    throw std::invalid_argument("PlotSpec: picture too small for its labels");
  }
  const AxisMap mx{lx.lo, lx.hi, area.x0, area.x1};
  const AxisMap my{ly.lo, ly.hi, area.y1, area.y0, spec.log_y};
  const AxisTicks xt = make_ticks(mx, area.width(), x_tick_spacing(s)),
                  yt = make_ticks(my, area.height(), y_tick_spacing(s));

  // Grid first, curves over it, frame and ticks on top.
  draw_grid(c, area, mx, xt, s, true);
  draw_grid(c, area, my, yt, s, false);
  c.clip(area);
  std::vector<Vec2> all_points;
  for (std::size_t k = 0; k < spec.series.size(); ++k) {
    const PlotSeries& se = spec.series[k];
    std::vector<Vec2> run;
    auto flush = [&] {
      c.polyline(run, float(spec.line_width), palette[k % std::size(palette)]);
      run.clear();
    };
    for (std::size_t i = 0; i < se.x.size(); ++i) {
      if (usable(se.x[i], se.y[i], spec.log_y)) {
        run.push_back({mx(se.x[i]), my(se.y[i])});
        all_points.push_back(run.back());
      } else {
        flush();
      }
    }
    flush();
  }
  c.clear_clip();
  draw_ticks(c, area, mx, xt, s, Side::bottom);
  draw_ticks(c, area, my, yt, s, Side::left);
  c.stroke_rect(area, std::max(1.0f, 0.6f * s), ink);
  draw_legend(c, spec, area, s, all_points);

  c.text(spec.x_label, (area.x0 + area.x1) / 2, area.y1 + 3.0f * ch, s, ink, Align::centre);
  c.text(spec.y_label, pad, (area.y0 + area.y1) / 2, s, ink, Align::centre, Align::start, true);
  if (!spec.title.empty()) {
    c.text(spec.title, (area.x0 + area.x1) / 2, pad, s + 0.5f, ink, Align::centre);
  }
  return c.finish();
}

}  // namespace fsi::render::detail
