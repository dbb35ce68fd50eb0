// Layout and drawing of one field frame:
//
//   t = 1.234 s                  title                    v_y [m/s]
//   +-----------------------------------------------+     +--+ 0.4
//   |  scalar field (per-pixel colour map)          |     |  | 0.2
//   |  mesh overlay, walls, interface contour       |     |  | 0.0
//   +-----------------------------------------------+     +--+ -0.2
//   ticks and labels in metres on the left and bottom edges
//
// Everything is sized in units of the capital height `ch`, itself proportional to
// the picture height, so a 320x240 thumbnail and a 1920x1080 frame look alike.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "axes.hpp"
#include "drawings.hpp"

namespace fsi::render::detail {
namespace {

constexpr Rgba outside_domain{238, 238, 238, 255};
constexpr Rgba mesh_ink{90, 90, 90, 110};
constexpr Rgba wall_ink{70, 70, 70, 255};
constexpr Rgba interface_ink{0, 0, 0, 255};

ViewWindow default_window(const FieldView& view) {
  // A small margin so the walls on the domain boundary are seen whole.
  const double dx = view.domain_max.x - view.domain_min.x;
  const double dy = view.domain_max.y - view.domain_min.y;
  const double m = 0.02 * std::max(dx, dy);
  return {view.domain_min.x - m, view.domain_min.y - m, view.domain_max.x + m,
          view.domain_max.y + m};
}

std::vector<Vec2> segment_points(const std::vector<Segment2>& segs, const AxisMap& mx,
                                 const AxisMap& my) {
  std::vector<Vec2> pts;
  pts.reserve(2 * segs.size());
  for (const Segment2& s : segs) {
    pts.push_back({mx(s.a.x), my(s.a.y)});
    pts.push_back({mx(s.b.x), my(s.b.y)});
  }
  return pts;
}

void draw_field(Canvas& c, const FieldView& view, const FrameSpec& spec, const AxisMap& mx,
                const AxisMap& my, const ColorRange& range, float s) {
  const QuantityInfo info = quantity_info(spec.quantity);
  const std::vector<double> values = nodal_values(view, spec.quantity);
  std::vector<Vec2> pos(view.nodes.size());
  std::vector<float> t(view.nodes.size());
  const double span = range.hi - range.lo;
  for (std::size_t i = 0; i < view.nodes.size(); ++i) {
    pos[i] = {mx(view.nodes[i].x), my(view.nodes[i].y)};
    t[i] = float((values[i] - range.lo) / span);
  }
  std::vector<unsigned> idx;
  idx.reserve(3 * view.triangles.size());
  for (const auto& tri : view.triangles) idx.insert(idx.end(), tri.begin(), tri.end());
  c.scalar_triangles(pos, t, idx, info.colormap);

  if (spec.show_mesh) {
    std::vector<Vec2> pts;
    pts.reserve(2 * view.mesh_edges.size());
    for (const auto& e : view.mesh_edges) pts.insert(pts.end(), {pos[e[0]], pos[e[1]]});
    c.segments(pts, std::max(0.6f, 0.35f * s), mesh_ink);
  }
  if (spec.show_walls) c.segments(segment_points(view.walls, mx, my), 1.6f * s, wall_ink, true);
  if (spec.show_interface) {
    c.segments(segment_points(view.interface, mx, my), 1.2f * s, interface_ink, true);
  }
}

// The colour bar right of the plot area: the whole map bottom (lo) to top (hi), framed,
// with nice ticks and its label (quantity and unit) above.
void draw_colorbar(Canvas& c, const Rect& bar, const ColorRange& range, const AxisTicks& ticks,
                   Colormap map, std::string_view label, float s) {
  const float ch = Canvas::text_height(s), lw = std::max(1.0f, 0.5f * s);
  c.colormap_rect(bar, map);
  c.stroke_rect(bar, lw, ink);
  draw_ticks(c, bar, AxisMap{range.lo, range.hi, bar.y1, bar.y0}, ticks, s, Side::right);
  c.text(label, bar.x0, bar.y0 - ch, s, ink, Align::start, Align::end);
}

}  // namespace

void validate(const FieldView& view) {
  const std::size_t n = view.nodes.size();
  auto check_field = [n](const std::vector<double>& f, const char* name) {
    if (!f.empty() && f.size() != n) {
      throw std::invalid_argument(std::string("FieldView: field ") + name + " has " +
                                  std::to_string(f.size()) + " values for " + std::to_string(n) +
                                  " nodes");
    }
  };
  check_field(view.vx, "vx");
  check_field(view.vy, "vy");
  check_field(view.p, "p");
  check_field(view.ux, "ux");
  check_field(view.uy, "uy");
  for (const auto& tri : view.triangles) {
    for (int k : tri) {
      if (k < 0 || std::size_t(k) >= n) {
        throw std::invalid_argument("FieldView: triangle node index " + std::to_string(k) +
                                    " out of range [0, " + std::to_string(n) + ")");
      }
    }
  }
  for (const auto& e : view.mesh_edges) {
    for (int k : e) {
      if (k < 0 || std::size_t(k) >= n) {
        throw std::invalid_argument("FieldView: mesh edge node index " + std::to_string(k) +
                                    " out of range");
      }
    }
  }
}

void draw_field_frame(Canvas& c, const FieldView& view, const FrameSpec& spec, Image& out) {
  validate(view);
  const ViewWindow w = spec.window.value_or(default_window(view));
  if (!(w.x1 > w.x0) || !(w.y1 > w.y0)) {
    throw std::invalid_argument("FrameSpec: the view window must have x0 < x1 and y0 < y1");
  }
  const QuantityInfo info = quantity_info(spec.quantity);
  const ColorRange range = spec.range.value_or(auto_range(view, spec.quantity));
  if (!(range.hi > range.lo)) {
    throw std::invalid_argument("FrameSpec: the colour range must have lo < hi");
  }
  c.begin(spec.width, spec.height, spec.supersample);
  const float s = auto_text_scale(spec.height, spec.text_scale), ch = Canvas::text_height(s);
  const float pad = 1.5f * ch;

  // Space around the plot area, from the outside in.
  AxisMap mx{w.x0, w.x1, 0, 1}, my{w.y0, w.y1, 1, 0};
  const float top = pad + 2.0f * ch;  // time stamp, title and colour bar label
  float left = pad, bottom = pad, right = pad;
  const float guess_w = spec.width * 0.7f, guess_h = spec.height * 0.7f;
  AxisTicks xt, yt;
  if (spec.show_axes) {
    xt = make_ticks(AxisMap{w.x0, w.x1, 0, guess_w}, guess_w, x_tick_spacing(s));
    yt = make_ticks(AxisMap{w.y0, w.y1, guess_h, 0}, guess_h, y_tick_spacing(s));
    left += max_label_width(yt, s) + 1.5f * ch + 2.0f * ch;  // labels, tick, "y [m]"
    bottom += 4.0f * ch;                                     // tick labels and "x [m]"
  }
  AxisTicks ct;
  float bar_band = 0;
  if (spec.show_colorbar) {
    ct = make_ticks(AxisMap{range.lo, range.hi, guess_h, 0}, guess_h, y_tick_spacing(s));
    const float label_w = Canvas::text_width(info.label, s);
    bar_band =
        2.5f * ch + 2.0f * ch + std::max(1.5f * ch + max_label_width(ct, s), label_w - 2 * ch);
  }
  Rect avail{left, top, spec.width - right - bar_band, spec.height - bottom};
  if (avail.width() < 10 || avail.height() < 10) {
    throw std::invalid_argument("FrameSpec: picture too small for its labels");
  }
  Rect area = avail;
  if (spec.keep_aspect) {
    const double ppm = std::min(avail.width() / (w.x1 - w.x0), avail.height() / (w.y1 - w.y0));
    const float aw = float(ppm * (w.x1 - w.x0)), ah = float(ppm * (w.y1 - w.y0));
    // Centre the plot area and its colour bar together.
    const float x0 = avail.x0 + (avail.width() - aw) / 2, y0 = avail.y0 + (avail.height() - ah) / 2;
    area = {x0, y0, x0 + aw, y0 + ah};
  }
  mx = {w.x0, w.x1, area.x0, area.x1};
  my = {w.y0, w.y1, area.y1, area.y0};

  c.fill_rect(area, outside_domain);
  c.clip(area);
  draw_field(c, view, spec, mx, my, range, s);
  c.clear_clip();
  const float frame_w = std::max(1.0f, 0.6f * s);
  c.stroke_rect(area, frame_w, ink);

  if (spec.show_axes) {
    xt = make_ticks(mx, area.width(), x_tick_spacing(s));
    yt = make_ticks(my, area.height(), y_tick_spacing(s));
    draw_ticks(c, area, mx, xt, s, Side::bottom);
    draw_ticks(c, area, my, yt, s, Side::left);
    c.text("x [m]", (area.x0 + area.x1) / 2, area.y1 + 3.0f * ch, s, ink, Align::centre);
    c.text("y [m]", area.x0 - 2.0f * ch - max_label_width(yt, s), (area.y0 + area.y1) / 2, s, ink,
           Align::centre, Align::end, true);
  }
  if (spec.show_colorbar) {
    const Rect bar{area.x1 + 2.5f * ch, area.y0, area.x1 + 4.5f * ch, area.y1};
    ct = make_ticks(AxisMap{range.lo, range.hi, bar.y1, bar.y0}, bar.height(), y_tick_spacing(s));
    draw_colorbar(c, bar, range, ct, info.colormap, info.label, s);
  }
  float time_right = area.x0;  // where the time stamp ends
  if (spec.show_time) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "t = %.*f s", std::clamp(spec.time_decimals, 0, 9), view.time_s);
    c.text(buf, area.x0, area.y0 - ch, s, ink, Align::start, Align::end);
    time_right = area.x0 + Canvas::text_width(buf, s);
  }
  if (!spec.title.empty()) {
    // Centred over the plot area, unless that would run into the time stamp. A title too
    // long for the picture is drawn smaller (down to the labels' size), and if it still
    // does not fit, cut with "..." rather than by the picture's edge.
    const float x_min = time_right + 2.0f * ch, room = spec.width - pad - x_min;
    std::string title = spec.title;
    float ts = s + 0.5f, tw = Canvas::text_width(title, ts);
    if (tw > room) {
      ts = std::max(s, ts * room / tw);
      tw = Canvas::text_width(title, ts);
    }
    if (tw > room) {
      std::size_t keep = spec.title.size();
      do {
        title = spec.title.substr(0, --keep) + "...";
        tw = Canvas::text_width(title, ts);
      } while (tw > room && keep > 0);
    }
    const float x = std::max((area.x0 + area.x1 - tw) / 2, x_min);
    c.text(title, x, area.y0 - ch, ts, ink, Align::start, Align::end);
  }
  c.finish(out);
}

}  // namespace fsi::render::detail
