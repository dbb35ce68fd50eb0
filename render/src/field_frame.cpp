// Layout and drawing of one field frame, sized for a talk: one text row on top, the
// field as tall as the picture allows below it.
//
//   t = 1.234 s                  title                         v_y [m/s]
//   +---------------------------------------------+ +----+     +--+ 0.2
//   |  scalar field (per-pixel colour map)        | |inset|    |  | 0.0
//   |  mesh overlay, walls, interface contour     | +----+     |  | -0.2
//   +---------------------------------------------+            +--+
//   x [m] -1.0 ... 1.0   (ticks in metres; "y [m]" and its ticks on the left edge)
//
// With FrameSpec::second_quantity the picture holds two such panels side by side, each
// with its colour bar. Everything is sized in units of the capital height `ch`, itself
// proportional to the picture height, so a 320x240 thumbnail and a 1920x1080 frame look
// alike.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "axes.hpp"
#include "drawings.hpp"

namespace fsi::render::detail {
namespace {

constexpr Rgba outside_domain{238, 238, 238, 255};
constexpr Rgba mesh_ink{90, 90, 90, 110};
constexpr Rgba wall_ink{70, 70, 70, 255};
constexpr Rgba interface_ink{0, 0, 0, 255};
// The contours of body1, body2, ... (FrameSpec::colour_bodies): dark, saturated colours
// that stand out on the light middle and the saturated ends of every colour map.
constexpr Rgba body_inks[] = {{0, 0, 0, 255}, {200, 0, 200, 255}, {0, 140, 0, 255}, {235, 120, 0, 255}};
constexpr Rgba inset_marker_ink{255, 255, 255, 255};
// The top text row's baseline sits this many capital heights above the field.
constexpr float text_row_gap = 0.6f;

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

// The field, mesh, walls and interface mapped by (mx, my); the caller clips.
void draw_field(Canvas& c, const FieldView& view, const FrameSpec& spec, Quantity q,
                const AxisMap& mx, const AxisMap& my, const ColorRange& range, float s) {
  const QuantityInfo info = quantity_info(q);
  const std::vector<double> values = nodal_values(view, q);
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
    int bodies = 1;
    if (spec.colour_bodies && view.interface_body.size() == view.interface.size())
      for (int b : view.interface_body) bodies = std::max(bodies, b + 1);
    if (bodies == 1) {
      c.segments(segment_points(view.interface, mx, my), 1.2f * s, interface_ink, true);
    } else {
      for (int b = 0; b < bodies; ++b) {
        std::vector<Segment2> own;
        for (std::size_t i = 0; i < view.interface.size(); ++i)
          if (view.interface_body[i] == b) own.push_back(view.interface[i]);
        c.segments(segment_points(own, mx, my), 1.2f * s, body_inks[b % std::size(body_inks)], true);
      }
    }
  }
}

// A quantity label left-aligned on the baseline y, its one-letter subscript typeset
// ("v_y [m/s]": a small y below the line after the v); other labels as they are.
void quantity_label(Canvas& c, std::string_view label, float x, float y, float s) {
  const std::size_t u = label.find('_');
  if (u == std::string_view::npos || u + 1 >= label.size()) {
    c.text(label, x, y, s, ink, Align::start, Align::end);
    return;
  }
  const std::string_view base = label.substr(0, u), sub = label.substr(u + 1, 1),
                         rest = label.substr(u + 2);
  const float ss = 0.7f * s, ch = Canvas::text_height(s);
  c.text(base, x, y, s, ink, Align::start, Align::end);
  x += Canvas::text_width(base, s) + 0.05f * ch;
  c.text(sub, x, y + 0.3f * ch, ss, ink, Align::start, Align::end);
  x += Canvas::text_width(sub, ss);
  c.text(rest, x, y, s, ink, Align::start, Align::end);
}

// The colour bar: the whole map bottom (lo) to top (hi), framed, with nice ticks on its
// right and its label (quantity and unit) above, on the picture's top text row.
void draw_colorbar(Canvas& c, const Rect& bar, const ColorRange& range, const AxisTicks& ticks,
                   Colormap map, std::string_view label, float s) {
  const float ch = Canvas::text_height(s), lw = std::max(1.0f, 0.5f * s);
  c.colormap_rect(bar, map);
  c.stroke_rect(bar, lw, ink);
  draw_ticks(c, bar, AxisMap{range.lo, range.hi, bar.y1, bar.y0}, ticks, s, Side::right);
  quantity_label(c, label, bar.x0, bar.y0 - text_row_gap * ch, s);
}

// Where one panel's parts go inside its share of the picture.
struct Panel {
  Quantity quantity;
  ColorRange range;
  Rect area;  // the field
  Rect bar;   // the colour bar (when shown)
  AxisMap mx, my;
  bool axis_labels = true;  // y tick labels, "y [m]" and "x [m]": on the first panel only
};

// Widths around a panel's field area [logical px]: y labels on the left, colour bar
// band on the right.
struct Margins {
  float left = 0, right = 0;
};

Margins panel_margins(const FrameSpec& spec, const ViewWindow& w, const ColorRange& range,
                      std::string_view label, bool axis_labels, float s, float guess_h) {
  const float ch = Canvas::text_height(s), pad = 0.8f * ch;
  Margins m{pad, pad};
  if (spec.show_axes && !axis_labels) m.left += 1.0f * ch;  // the tick marks
  if (spec.show_axes && axis_labels) {
    const AxisTicks yt = make_ticks(AxisMap{w.y0, w.y1, guess_h, 0}, guess_h, y_tick_spacing(s));
    // rotated "y [m]" (ch tall), a gap, the tick labels, the tick and its gap; at least
    // room for "x [m]" before the first x tick label (half of which may stick out left)
    m.left += std::max(ch + 0.8f * ch + max_label_width(yt, s) + 1.0f * ch,
                       Canvas::text_width("x [m]", s) + 1.0f * ch + 1.5f * ch);
  }
  if (spec.show_colorbar) {
    const AxisTicks ct =
        make_ticks(AxisMap{range.lo, range.hi, guess_h, 0}, guess_h, y_tick_spacing(s));
    const float bar_and_ticks = 1.5f * ch + 1.3f * ch + 1.0f * ch + max_label_width(ct, s);
    m.right += std::max(bar_and_ticks, 1.5f * ch + Canvas::text_width(label, s));
  }
  return m;
}

// The colour bar right of a field area, as tall as it less 0.75 ch at the top: room
// between the label above the bar and the label of its top tick.
Rect colorbar_box(const Rect& area, float ch) {
  return {area.x1 + 1.5f * ch, area.y0 + 0.75f * ch, area.x1 + 2.8f * ch, area.y1};
}

// Lays the panels out side by side between `top` and `bottom`: field areas of one size
// (the window's aspect kept if asked), as large as the picture allows with every
// panel's margins, the row of them centred.
std::vector<Panel> layout_panels(const FrameSpec& spec, const ViewWindow& w,
                                 const std::vector<std::pair<Quantity, ColorRange>>& panels,
                                 float top, float bottom, float s) {
  const float ch = Canvas::text_height(s);
  std::vector<Margins> margins;
  float margin_sum = 0;
  for (std::size_t i = 0; i < panels.size(); ++i) {
    margins.push_back(panel_margins(spec, w, panels[i].second, quantity_info(panels[i].first).label,
                                    i == 0, s, bottom - top));
    margin_sum += margins.back().left + margins.back().right;
  }
  const float n = float(panels.size());
  float aw = (float(spec.width) - margin_sum) / n, ah = bottom - top;
  if (aw < 10 || ah < 10) throw std::invalid_argument("FrameSpec: picture too small for its labels");
  if (spec.keep_aspect) {
    const double ppm = std::min(aw / (w.x1 - w.x0), ah / (w.y1 - w.y0));
    aw = float(ppm * (w.x1 - w.x0));
    ah = float(ppm * (w.y1 - w.y0));
  }
  float x = (float(spec.width) - margin_sum - n * aw) / 2;
  const float y = top + (bottom - top - ah) / 2;
  std::vector<Panel> laid;
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const Rect area{x + margins[i].left, y, x + margins[i].left + aw, y + ah};
    laid.push_back({panels[i].first, panels[i].second, area, colorbar_box(area, ch),
                    AxisMap{w.x0, w.x1, area.x0, area.x1}, AxisMap{w.y0, w.y1, area.y1, area.y0},
                    i == 0});
    x = area.x1 + margins[i].right;
  }
  return laid;
}

// The inset's box in the upper right corner of `area`: 45 % of its width, 2:1.
Rect inset_box(const Rect& area, float ch) {
  const float w = 0.45f * area.width(), h = std::min(w / 2.0f, 0.4f * area.height());
  const float m = 0.6f * ch;
  return {area.x1 - m - w, area.y0 + m, area.x1 - m, area.y0 + m + h};
}

void draw_inset(Canvas& c, const FieldView& view, const FrameSpec& spec, const Panel& p,
                const ViewWindow& win, float s) {
  const float ch = Canvas::text_height(s);
  const Rect box = inset_box(p.area, ch);
  // The window's outline in the panel (at least a few pixels tall: a film is thin).
  Rect mark{p.mx(win.x0), p.my(win.y1), p.mx(win.x1), p.my(win.y0)};
  if (mark.height() < 4) mark.y0 = (mark.y0 + mark.y1) / 2 - 2, mark.y1 = mark.y0 + 4;
  c.stroke_rect(mark, std::max(1.0f, 0.5f * s), inset_marker_ink);
  c.segments({{mark.x1, mark.y0}, {box.x1, box.y1}, {mark.x0, mark.y0}, {box.x0, box.y1}},
             std::max(1.0f, 0.4f * s), {255, 255, 255, 170});
  const AxisMap mx{win.x0, win.x1, box.x0, box.x1}, my{win.y0, win.y1, box.y1, box.y0};
  c.fill_rect(box, outside_domain);
  c.clip(box);
  draw_field(c, view, spec, p.quantity, mx, my, p.range, s);
  c.clear_clip();
  c.stroke_rect(box, std::max(1.0f, 0.6f * s), ink);
  // How high the window is, so the eye can read the stretched picture.
  const double h = win.y1 - win.y0;
  char buf[64];
  if (h < 0.1) {
    std::snprintf(buf, sizeof buf, "%.3g mm high", h * 1e3);
  } else {
    std::snprintf(buf, sizeof buf, "%.3g m high", h);
  }
  const float ts = std::max(1.0f, s - 0.5f), tch = Canvas::text_height(ts);
  // Under the box, right-aligned, on a light patch so it reads over any colour.
  const float tag_w = Canvas::text_width(buf, ts) + 1.0f * tch;
  const Rect tag{box.x1 - tag_w, box.y1 + 0.3f * tch, box.x1, box.y1 + 2.3f * tch};
  c.fill_rect(tag, {255, 255, 255, 210});
  c.text(buf, tag.x0 + 0.5f * tch, tag.y0 + 0.5f * tch, ts, ink);
}

void draw_panel(Canvas& c, const FieldView& view, const FrameSpec& spec, const Panel& p, float s) {
  const float ch = Canvas::text_height(s);
  c.fill_rect(p.area, outside_domain);
  c.clip(p.area);
  draw_field(c, view, spec, p.quantity, p.mx, p.my, p.range, s);
  c.clear_clip();
  if (spec.inset) draw_inset(c, view, spec, p, *spec.inset, s);
  c.stroke_rect(p.area, std::max(1.0f, 0.6f * s), ink);
  if (spec.show_axes) {
    const AxisTicks xt = make_ticks(p.mx, p.area.width(), x_tick_spacing(s));
    AxisTicks yt = make_ticks(p.my, p.area.height(), y_tick_spacing(s));
    draw_ticks(c, p.area, p.mx, xt, s, Side::bottom);
    if (!p.axis_labels) {
      // A second panel shows the first one's window: its y ticks as marks only.
      for (std::string& l : yt.labels) l.clear();
      draw_ticks(c, p.area, p.my, yt, s, Side::left);
    } else {
      draw_ticks(c, p.area, p.my, yt, s, Side::left);
      // "x [m]" opens the row of tick labels (its own row below them would cost the
      // field a line of height): right-aligned a capital height before the first label.
      float first_label = p.area.x0;
      if (!xt.values.empty()) {
        first_label = std::min(first_label, p.mx(xt.values.front()) -
                                                Canvas::text_width(xt.labels.front(), s) / 2);
      }
      c.text("x [m]", first_label - 1.0f * ch, p.area.y1 + 1.0f * ch, s, ink, Align::end);
      c.text("y [m]", p.area.x0 - 1.8f * ch - max_label_width(yt, s), (p.area.y0 + p.area.y1) / 2,
             s, ink, Align::centre, Align::end, true);
    }
  }
  if (spec.show_colorbar) {
    const AxisTicks ct = make_ticks(AxisMap{p.range.lo, p.range.hi, p.bar.y1, p.bar.y0},
                                    p.bar.height(), y_tick_spacing(s));
    const QuantityInfo info = quantity_info(p.quantity);
    draw_colorbar(c, p.bar, p.range, ct, info.colormap, info.label, s);
  }
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
  if (spec.inset && !(spec.inset->x1 > spec.inset->x0 && spec.inset->y1 > spec.inset->y0)) {
    throw std::invalid_argument("FrameSpec: the inset window must have x0 < x1 and y0 < y1");
  }
  std::vector<std::pair<Quantity, ColorRange>> panels{
      {spec.quantity, spec.range.value_or(auto_range(view, spec.quantity))}};
  if (spec.second_quantity) {
    panels.emplace_back(*spec.second_quantity,
                        spec.second_range.value_or(auto_range(view, *spec.second_quantity)));
  }
  for (const auto& [q, range] : panels) {
    if (!(range.hi > range.lo)) {
      throw std::invalid_argument("FrameSpec: the colour range must have lo < hi");
    }
  }
  c.begin(spec.width, spec.height, spec.supersample);
  const float s = auto_text_scale(spec.height, spec.text_scale), ch = Canvas::text_height(s);
  const float pad = 0.8f * ch;

  // One text row on top (time stamp, title, colour bar labels: the title's capitals are
  // the tallest), one below the field (the x tick labels and "x [m]", with descenders).
  const bool top_row = spec.show_time || !spec.title.empty() || spec.show_colorbar;
  const float title_cap = Canvas::text_height(s + 0.5f);
  const float top = top_row ? 0.5f * ch + title_cap + text_row_gap * ch : pad;
  const float bottom = spec.height - (spec.show_axes ? 2.9f * ch : pad);
  const std::vector<Panel> laid = layout_panels(spec, w, panels, top, bottom, s);
  for (const Panel& p : laid) draw_panel(c, view, spec, p, s);

  const Rect& first = laid.front().area;
  float time_right = first.x0;  // where the time stamp ends
  if (spec.show_time) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "t = %.*f s", std::clamp(spec.time_decimals, 0, 9), view.time_s);
    c.text(buf, first.x0, first.y0 - text_row_gap * ch, s, ink, Align::start, Align::end);
    time_right = first.x0 + Canvas::text_width(buf, s);
  }
  // The title's room: between the time stamp and the first colour bar's label.
  const float x_min = time_right + 2.0f * ch;
  const float x_max = spec.show_colorbar ? laid.front().bar.x0 - 2.0f * ch
                      : laid.size() > 1  ? laid.back().area.x0 - 2.0f * ch
                                         : spec.width - pad;
  const float room = x_max - x_min;
  if (!spec.title.empty() && room >= 3.0f * ch) {
    // Centred over the (first) field, unless that would run into the time stamp or a
    // colour bar label. A title too long for its room is drawn smaller (down to the
    // labels' size), and if it still does not fit, cut with "..." rather than by the
    // picture's edge; with no room at all (two panels on a thumbnail) it is left out.
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
    const float centre = (first.x0 + first.x1) / 2;
    const float x = std::clamp(centre - tw / 2, x_min, std::max(x_min, x_max - tw));
    c.text(title, x, first.y0 - text_row_gap * ch, ts, ink, Align::start, Align::end);
  }
  c.finish(out);
}

}  // namespace fsi::render::detail

namespace fsi::render {

std::optional<ViewWindow> film_window(const FieldView& view) {
  if (view.interface.empty()) return std::nullopt;
  double lo = INFINITY, hi = -INFINITY;
  for (const Segment2& sg : view.interface) {
    lo = std::min({lo, sg.a.y, sg.b.y});
    hi = std::max({hi, sg.a.y, sg.b.y});
  }
  const double radius = 0.5 * (hi - lo), floor = view.domain_min.y;
  const double gap = lo - floor;
  if (!(radius > 0) || gap > 0.5 * radius) return std::nullopt;
  double x0 = INFINITY, x1 = -INFINITY;
  for (const Segment2& sg : view.interface) {
    for (const Point2& q : {sg.a, sg.b}) {
      if (q.y <= lo + 0.6 * radius) x0 = std::min(x0, q.x), x1 = std::max(x1, q.x);
    }
  }
  // The film fills most of the window's height, the body's underside shows above it.
  const double h = std::max(gap, 2e-3 * radius);
  const double margin = 0.05 * (x1 - x0);
  return ViewWindow{x0 - margin, floor - 0.15 * h, x1 + margin, lo + 0.6 * h};
}

}  // namespace fsi::render
