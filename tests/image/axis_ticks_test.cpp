#include <gtest/gtest.h>

#include <cmath>
#include <fsi/axis_ticks.hpp>

#include "../../render/src/axes.hpp"  // the frame axes' tick placement (internal)

namespace fsi::render {
namespace {

TEST(AxisTicks, NiceStepsAreOneTwoFive) {
  EXPECT_DOUBLE_EQ(nice_step(0, 1, 5), 0.2);
  EXPECT_DOUBLE_EQ(nice_step(0, 10, 5), 2.0);
  EXPECT_DOUBLE_EQ(nice_step(-1, 1, 4), 0.5);
  EXPECT_DOUBLE_EQ(nice_step(0, 1e-3, 5), 2e-4);
  EXPECT_DOUBLE_EQ(nice_step(0, 0, 5), 1.0);  // degenerate: any positive step
}

TEST(AxisTicks, TicksCoverTheRangeWithoutNegativeZero) {
  const std::vector<double> t = nice_ticks(-1, 1, 4);
  ASSERT_EQ(t.size(), 5u);
  EXPECT_DOUBLE_EQ(t.front(), -1.0);
  EXPECT_DOUBLE_EQ(t.back(), 1.0);
  EXPECT_FALSE(std::signbit(t[2]));
  const std::vector<double> u = nice_ticks(0.13, 0.87, 5);
  EXPECT_DOUBLE_EQ(u.front(), 0.2);
  EXPECT_DOUBLE_EQ(u.back(), 0.8);
}

TEST(AxisTicks, LabelsHaveTheDecimalsTheStepNeeds) {
  EXPECT_EQ(format_tick(0.5, 0.5), "0.5");
  EXPECT_EQ(format_tick(1.0, 0.5), "1.0");
  EXPECT_EQ(format_tick(0.0, 0.5), "0.0");
  EXPECT_EQ(format_tick(20, 10), "20");
  EXPECT_EQ(format_tick(-0.25, 0.05), "-0.25");
  EXPECT_EQ(format_tick(2e-4, 2e-4), "2e-04");
  EXPECT_EQ(format_tick(1.5e6, 5e5), "1.5e+06");
}

TEST(AxisTicks, LogTicks) {
  const std::vector<double> d = log_ticks(1e-6, 1, 6);
  ASSERT_EQ(d.size(), 7u);
  EXPECT_DOUBLE_EQ(d.front(), 1e-6);
  const std::vector<double> short_axis = log_ticks(0.08, 0.6, 6);
  EXPECT_GE(short_axis.size(), 3u);  // 0.1, 0.2, 0.5
}

TEST(AxisTicks, AShortAxisKeepsItsLabelsApart) {
  // 5 cm of a letterboxed 1 m x 5 cm zoom drawn 12 px high, labels 35 px apart wanted:
  // one label, not three on top of each other.
  const detail::AxisMap short_axis{-0.75, -0.70, 112, 100};
  const detail::AxisTicks few = detail::make_ticks(short_axis, 12, 35);
  ASSERT_GE(few.values.size(), 1u);
  for (std::size_t i = 1; i < few.values.size(); ++i) {
    EXPECT_GE(std::abs(short_axis(few.values[i]) - short_axis(few.values[i - 1])), 17.5f);
  }
  EXPECT_EQ(few.labels.size(), few.values.size());
  // A long axis keeps its ticks: 0..1 over 350 px, one per 35 px wanted.
  const detail::AxisMap long_axis{0, 1, 350, 0};
  EXPECT_GE(detail::make_ticks(long_axis, 350, 35).values.size(), 6u);
}

}  // namespace
}  // namespace fsi::render
