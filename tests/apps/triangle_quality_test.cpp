// fsi-step's `quality`: the largest angles and the smallest area of a view's triangles.
#include "triangle_quality.hpp"

#include <gtest/gtest.h>

namespace {

TEST(TriangleQuality, FindsTheFlattestAndTheSmallestTriangle) {
  fsi::FieldView view;
  // A right triangle (largest angle 90), a flat one (171.8 deg: 5.6 cm base, 2 mm
  // high, apex at its middle) and a small right one.
  view.nodes = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {2.056, 0}, {2.028, 0.002}, {3, 0}, {3.001, 0}, {3, 0.001}};
  view.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}};
  const fsi::app::TriangleQuality q = fsi::app::measure_triangles(view);
  EXPECT_EQ(q.triangles, 3);
  EXPECT_EQ(q.max_angle_above_150_deg, 1);
  EXPECT_EQ(q.max_angle_above_160_deg, 1);
  EXPECT_EQ(q.max_angle_above_170_deg, 1);
  EXPECT_NEAR(q.worst_max_angle_deg, 180.0 - 2 * 4.0856, 1e-3);  // 2 atan(2/28)
  EXPECT_NEAR(q.worst_at.x, 2.028, 1e-12);
  EXPECT_NEAR(q.smallest_area_m2, 0.5e-6, 1e-18);
  EXPECT_NEAR(q.smallest_at.x, 3.0 + 0.001 / 3, 1e-12);
}

TEST(TriangleQuality, AnEmptyViewHasNoTriangles) {
  const fsi::app::TriangleQuality q = fsi::app::measure_triangles(fsi::FieldView{});
  EXPECT_EQ(q.triangles, 0);
  EXPECT_EQ(q.worst_max_angle_deg, 0.0);
  EXPECT_EQ(q.smallest_area_m2, 0.0);
}

}  // namespace
