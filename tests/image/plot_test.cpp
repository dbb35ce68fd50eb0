#include <gtest/gtest.h>

#include <cmath>
#include <fsi/plot.hpp>
#include <fsi/renderer.hpp>

#include "image/golden.hpp"

namespace fsi::render {
namespace {

PlotSpec functionals_plot() {
  PlotSpec p;
  p.title = "Ball drop";
  p.y_label = "[m]";
  p.width = 320;
  p.height = 240;
  PlotSeries gap{"gap", {}, {}}, width{"width", {}, {}};
  for (int i = 0; i <= 100; ++i) {
    const double t = 0.02 * i;
    gap.x.push_back(t);
    gap.y.push_back(0.5 * std::exp(-1.5 * t));
    width.x.push_back(t);
    width.y.push_back(0.6 + 0.03 * std::sin(6 * t));
  }
  p.series = {gap, width};
  return p;
}

TEST(Plot, TwoSeriesGolden) {
  Renderer r{GlBackend::osmesa};
  testing::expect_matches_golden("plot_functionals", r.plot(functionals_plot()));
}

TEST(Plot, LogAxisGolden) {
  PlotSpec p = functionals_plot();
  p.log_y = true;
  p.title = "mass error";
  p.series[0].y[10] = 0.0;  // not drawable on a log axis: breaks the line, no crash
  Renderer r{GlBackend::osmesa};
  testing::expect_matches_golden("plot_log", r.plot(p));
}

TEST(Plot, FreeFunctionAndErrors) {
  PlotSpec p = functionals_plot();
  const Image im = plot(p);
  EXPECT_EQ(im.width, 320);
  EXPECT_EQ(im.height, 240);
  p.series[1].y.pop_back();
  EXPECT_THROW(plot(p), std::invalid_argument);
}

}  // namespace
}  // namespace fsi::render
