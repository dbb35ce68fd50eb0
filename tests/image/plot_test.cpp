#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fsi/image_compare.hpp>
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

TEST(Plot, ZoomScalesTheYAxisToWhatIsShown) {
  // x_min = 1: the y axis spans the visible part of the curve, exactly as if the points
  // left of x_min were not there (a zoom on the contact interval must not stay scaled
  // to the fall from 0.6 m).
  PlotSpec full = functionals_plot();
  full.series.resize(1);
  full.x_min = 1.0;
  PlotSpec cut = full;
  PlotSeries& g = cut.series[0];
  const auto first = std::find_if(g.x.begin(), g.x.end(), [](double x) { return x >= 1.0; });
  const auto k = first - g.x.begin();
  g.x.erase(g.x.begin(), g.x.begin() + k);
  g.y.erase(g.y.begin(), g.y.begin() + k);
  const ImageComparison c = compare_images(plot(cut), plot(full));
  EXPECT_TRUE(c.same) << c.verdict;
  PlotSpec unscaled = cut;
  unscaled.y_min = 0.0;
  unscaled.y_max = 0.5;
  EXPECT_FALSE(compare_images(plot(unscaled), plot(full)).same);
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
