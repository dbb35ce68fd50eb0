#pragma once
/// \file plot.hpp
/// Line plots of functionals over time, drawn like a paper figure: framed axes with nice
/// ticks and a light grid, tick labels, axis labels, a title and a legend.
#include <optional>
#include <string>
#include <vector>

#include "fsi/image.hpp"

namespace fsi::render {

/// One curve. Points with a non-finite x or y (or y <= 0 on a log axis) break the line.
struct PlotSeries {
  std::string label;      ///< legend entry; empty = not listed
  std::vector<double> x;  ///< abscissae, same length as y
  std::vector<double> y;  ///< ordinates
};

struct PlotSpec {
  std::string title;
  std::string x_label = "t [s]";
  std::string y_label;
  std::vector<PlotSeries> series;  ///< coloured in turn from a colour-blind-safe palette
  bool log_y = false;              ///< logarithmic y axis (decade ticks)
  std::optional<double> x_min, x_max, y_min, y_max;  ///< fixed limits; unset = data range
  int width = 960;                                   ///< [px]
  int height = 600;                                  ///< [px]
  double text_scale = 0;                             ///< 0 = automatic from the height
  double line_width = 2.0;                           ///< [px]
  int supersample = 2;                               ///< 1..4
};

/// Draws a plot with a temporary renderer (FSI_GL_BACKEND selects the backend); use
/// Renderer::plot to reuse a context. Throws std::invalid_argument on x/y length mismatch.
Image plot(const PlotSpec& spec);

}  // namespace fsi::render
