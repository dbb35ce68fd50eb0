// The four plots of a run. Each is one PlotSpec: a series picked out of the history.
#include "functional_plots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fsi/plot.hpp>
#include <fsi/png.hpp>
#include <functional>

namespace fsi::app {
namespace {

render::PlotSpec one_series_plot(const FunctionalsHistory& h, const std::string& title,
                                 const std::string& label, const std::string& y_label,
                                 const std::function<double(const Functionals&)>& pick) {
  render::PlotSpec spec;
  spec.title = title;
  spec.y_label = y_label;
  render::PlotSeries s{label, h.time_s, {}};
  s.y.reserve(h.values.size());
  for (const Functionals& f : h.values) s.y.push_back(pick(f));
  spec.series = {std::move(s)};
  return spec;
}

std::size_t positive_count(const render::PlotSpec& spec) {
  std::size_t n = 0;
  for (double y : spec.series.front().y) n += (std::isfinite(y) && y > 0) ? 1 : 0;
  return n;
}

/// On a log axis, a distance of 1e-17 m (rounding at real contact) would squeeze the
/// approach into the top of the plot: values below `fraction` times the largest are
/// drawn at that floor, and the legend says so.
void floor_small_values(render::PlotSpec& spec, double fraction) {
  render::PlotSeries& s = spec.series.front();
  double largest = 0;
  for (double y : s.y) largest = std::isfinite(y) ? std::max(largest, y) : largest;
  const double floor = fraction * largest;
  bool floored = false;
  for (double& y : s.y) {
    if (std::isfinite(y) && y < floor) y = floor, floored = true;
  }
  if (floored) {
    char note[64];
    std::snprintf(note, sizeof note, " (< %.1e m drawn at it)", floor);
    s.label += note;
  }
}

}  // namespace

std::vector<std::filesystem::path> write_functional_plots(render::Renderer& renderer,
                                                          const FunctionalsHistory& history,
                                                          const std::string& title,
                                                          const std::filesystem::path& folder) {
  if (history.time_s.size() < 2) return {};
  struct Plot {
    const char* file;
    render::PlotSpec spec;
  };
  Plot plots[] = {
      {"plot_distance.png",
       one_series_plot(history, title + ": minimal distance to the walls", "min distance",
                       "distance [m]", [](const Functionals& f) { return f.min_distance_m; })},
      {"plot_height.png",
       one_series_plot(history, title + ": height of the ball", "top - bottom", "height [m]",
                       [](const Functionals& f) { return f.top_y_m - f.bottom_y_m; })},
      {"plot_velocity.png",
       one_series_plot(history, title + ": mean vertical velocity of the solid", "mean v_y",
                       "v_y [m/s]", [](const Functionals& f) { return f.mean_vy_mps; })},
      {"plot_mass.png",
       one_series_plot(history, title + ": relative mass error", "j_mass", "j_mass [1]",
                       [](const Functionals& f) { return f.mass_error; })},
  };
  // The approach to the wall and the mass error span decades: log y, when there are
  // enough positive values to draw (real contact gives distance 0, t = 0 mass error 0).
  plots[0].spec.log_y = positive_count(plots[0].spec) >= 2;
  plots[3].spec.log_y = positive_count(plots[3].spec) >= 2;
  if (plots[0].spec.log_y) floor_small_values(plots[0].spec, 1e-4);
  std::vector<std::filesystem::path> written;
  for (const Plot& p : plots) {
    const std::filesystem::path file = folder / p.file;
    render::write_png(file, renderer.plot(p.spec));
    written.push_back(file);
  }
  return written;
}

}  // namespace fsi::app
