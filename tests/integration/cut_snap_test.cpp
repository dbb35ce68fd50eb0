// numerics.cut_snap: cuts closer than cut_snap x (patch side) to a corner go through the
// corner in the engine's geometry (t = 0 and every step), and the run goes on normally.
#include <fsi/engine.hpp>
#include <gtest/gtest.h>

#include <algorithm>

#include "test_scenarios.hpp"

namespace {

int corners_on_the_interface(const fsi::Engine& engine) {
  const auto& sign = engine.state().corner_sign;
  return static_cast<int>(std::count(sign.begin(), sign.end(), 0));
}

TEST(CutSnap, ALargerSnapPutsTheInterfaceThroughMoreCorners) {
  fsi::Scenario s = fsi::testing::coarse_example1();
  fsi::Engine fine_snap(s);  // the default 1e-6: no cut of the round ball is that close
  s.numerics.cut_snap = 0.25;
  fsi::Engine coarse_snap(s);
  // Corner signs are 0 only for corners on the interface (plus non-corner nodes).
  EXPECT_GT(corners_on_the_interface(coarse_snap), corners_on_the_interface(fine_snap));
  const double area = fine_snap.state().functionals.solid_area_m2;
  // Snapping moves the interface by at most a quarter of a patch side.
  EXPECT_NE(coarse_snap.state().functionals.solid_area_m2, area);
  EXPECT_NEAR(coarse_snap.state().functionals.solid_area_m2, area, 0.05 * area);
  for (int i = 0; i < 3; ++i) {
    const fsi::StepReport report = coarse_snap.step();
    EXPECT_TRUE(report.converged) << report.message;
  }
}

}  // namespace
