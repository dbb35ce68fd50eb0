#pragma once
/// \file functional_plots.hpp
/// The functionals of a run over time and their plots, like the chapter's Fig. 12.6:
///   plot_distance.png  minimal distance ball-wall (log y: the last 1e-3 m are visible)
///   plot_height.png    height of the ball (top - bottom of the interface)
///   plot_velocity.png  solid-averaged vertical velocity
///   plot_mass.png      relative mass error j_mass (log y)
#include <filesystem>
#include <fsi/renderer.hpp>
#include <fsi/state.hpp>
#include <string>
#include <vector>

namespace fsi::app {

/// One sample per time level.
struct FunctionalsHistory {
  std::vector<double> time_s;
  std::vector<Functionals> values;

  void add(double t_s, const Functionals& f) {
    time_s.push_back(t_s);
    values.push_back(f);
  }
};

/// Writes the four plots into `folder` and returns the files written. `title` heads
/// each plot (e.g. the scenario name). Needs at least two samples; fewer: none written.
std::vector<std::filesystem::path> write_functional_plots(render::Renderer& renderer,
                                                          const FunctionalsHistory& history,
                                                          const std::string& title,
                                                          const std::filesystem::path& folder);

}  // namespace fsi::app
