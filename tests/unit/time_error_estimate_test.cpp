// The local error of a dG(0) step in the body's position (core/time_error_estimate.hpp)
// and the step length it allows.
#include "core/time_error_estimate.hpp"

#include "core/time_step_choice.hpp"
#include "fe/cut_mesh.hpp"
#include "fsi/state.hpp"
#include "mesh/patch_mesh.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace {

using fsi::core::displacement_error_estimate;
using fsi::core::step_for_error;

/// The unit square in 4 x 4 patches; the solid below y0.
struct Levels {
  fsi::mesh::PatchMesh mesh;
  fsi::fe::CutMesh below(double y0) const {
    return fsi::fe::build_cut_mesh(mesh,
                                   fsi::fe::cut_data(mesh, [=](const fsi::mesh::Vec2& x) { return x.y() - y0; }));
  }
  Levels() {
    fsi::MeshSpec spec;
    fsi::BlockSpec b;
    b.x = {fsi::AxisPiece{0.0, 1.0, 4, 0.0, 0.0}};
    b.y = {fsi::AxisPiece{0.0, 1.0, 4, 0.0, 0.0}};
    spec.blocks = {b};
    mesh = fsi::mesh::build_patch_mesh(spec, {});
  }
};

/// u = (0, uy) at every node of the solid of `cut`, the fluid's nodes far off (5 m).
Eigen::VectorXd uniform_displacement(const fsi::fe::CutMesh& cut, double uy) {
  const int nodes = static_cast<int>(cut.touches_solid.size());
  Eigen::VectorXd x = Eigen::VectorXd::Zero(fsi::kFieldsPerNode * nodes);
  for (int i = 0; i < nodes; ++i) x[fsi::kFieldsPerNode * i + fsi::kUy] = cut.touches_solid[i] ? uy : 5.0;
  return x;
}

TEST(TimeErrorEstimate, ZeroForUniformMotionAndTheSecondDifferenceForAcceleration) {
  const Levels l;
  const auto a = l.below(0.5), b = l.below(0.49), c = l.below(0.48);
  // Steps of 0.01 s and 0.02 s: at constant velocity -1 m/s the body moves -0.01, -0.02 m.
  EXPECT_NEAR(displacement_error_estimate(a, uniform_displacement(a, 0.0), b, uniform_displacement(b, -0.01), c,
                                          uniform_displacement(c, -0.03), 0.01, 0.02),
              0.0, 1e-15);
  // Accelerating at -a = -2 m/s^2 from rest, equal steps k = 0.01 s: u = -t^2, the
  // second difference 2 k^2 = 2e-4 m, the estimate k / 2k of it = 1e-4 m = k^2 a / 2.
  EXPECT_NEAR(displacement_error_estimate(a, uniform_displacement(a, 0.0), b, uniform_displacement(b, -1e-4), c,
                                          uniform_displacement(c, -4e-4), 0.01, 0.01),
              1e-4, 1e-15);
  // Interface and fluid nodes do not count: the same with the fluid's values changed.
  Eigen::VectorXd next = uniform_displacement(c, -4e-4);
  for (int i = 0; i < static_cast<int>(c.touches_solid.size()); ++i)
    if (c.touches_fluid[i]) next[fsi::kFieldsPerNode * i + fsi::kUy] = 7.0;
  EXPECT_NEAR(displacement_error_estimate(a, uniform_displacement(a, 0.0), b, uniform_displacement(b, -1e-4), c,
                                          next, 0.01, 0.01),
              1e-4, 1e-15);
}

TEST(TimeErrorEstimate, NoEstimateWithoutTheLevelsItNeeds) {
  const Levels l;
  const auto a = l.below(0.5);
  const Eigen::VectorXd x = uniform_displacement(a, 0.0);
  EXPECT_LT(displacement_error_estimate(a, x, a, x, a, x, 0.0, 0.01), 0.0);  // the first step
  const auto none = l.below(-1.0);                                           // no solid
  const Eigen::VectorXd y = uniform_displacement(none, 0.0);
  EXPECT_LT(displacement_error_estimate(none, y, none, y, none, y, 0.01, 0.01), 0.0);
  const Eigen::VectorXd shorter = x.head(x.size() - fsi::kFieldsPerNode);
  EXPECT_LT(displacement_error_estimate(a, x, a, x, a, shorter, 0.01, 0.01), 0.0);
}

TEST(TimeErrorEstimate, StepForErrorScalesWithTheSquareRootAndIsBounded) {
  // Error 4x the tolerance: half the step, times the safety factor 0.8.
  EXPECT_DOUBLE_EQ(step_for_error(0.01, 4e-6, 1e-6), 0.01 * 0.8 * 0.5);
  EXPECT_DOUBLE_EQ(step_for_error(0.01, 1e-9, 1e-6), 0.02);      // at most twice
  EXPECT_DOUBLE_EQ(step_for_error(0.01, 1.0, 1e-6), 0.0025);     // at least a quarter
  EXPECT_DOUBLE_EQ(step_for_error(0.01, 0.0, 1e-6), 0.02);
  EXPECT_TRUE(std::isinf(step_for_error(0.01, -1.0, 1e-6)));     // no estimate: no limit
  EXPECT_TRUE(std::isinf(step_for_error(0.01, 1e-6, 0.0)));      // control off
}

TEST(TimeErrorEstimate, ChooseTimeStepGoesBelowKOnlyWithErrorControl) {
  fsi::NumericsSpec n = fsi::numerics_for(fsi::Method::chapter);
  n.time_step_s = 2e-3;
  n.time_step_max_doublings = 3;  // up to 1.6e-2 s
  fsi::Functionals far;
  far.min_distance_m = 1.0;
  EXPECT_DOUBLE_EQ(fsi::core::choose_time_step(n, far, 1.0, 0.0, 6e-4), 2e-3);  // control off: k
  n.time_error_tolerance_m = 1e-6;
  EXPECT_DOUBLE_EQ(fsi::core::choose_time_step(n, far, 1.0, 0.0, 6e-4), 5e-4);
  EXPECT_DOUBLE_EQ(fsi::core::choose_time_step(n, far, 1.0, 0.0, 1e-6), 2.5e-4);  // at least k / 8
  EXPECT_DOUBLE_EQ(fsi::core::choose_time_step(n, far, 1.0, 0.0, 5e-3), 4e-3);
}

}  // namespace
