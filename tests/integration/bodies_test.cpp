// Several bodies through the engine: two balls thrown at each other without gravity
// (assets/scenarios/bodies/two_balls_collide.json) stay mirror-symmetric, the penalty
// force stops them apart and they separate; the three balls of assets/scenarios/three_balls.json start
// with each body's mass error under 1 %; a checkpoint continues bit-identically.
#include <fsi/engine.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>

namespace {

fsi::Scenario shipped(const std::string& name) {
  return fsi::load_scenario(std::filesystem::path(FSI_SOURCE_DIR) / "assets/scenarios" / name);
}

TEST(Bodies, TwoBallsThrownAtEachOtherStayMirrorSymmetric) {
  fsi::Engine engine(shipped("bodies/two_balls_collide.json"));
  for (int i = 0; i < 25; ++i) {
    const fsi::StepReport r = engine.step();
    ASSERT_TRUE(r.accepted && r.converged) << "step " << i << ": " << r.message;
    const auto& b = engine.state().functionals.bodies;
    ASSERT_EQ(b.size(), 2u);
    // Mirrored about x = 0 and about y = 0 (measured: 6e-15 m to t = 2 s, tools/study-bodies).
    EXPECT_LT(std::abs(b[0].centroid_x_m + b[1].centroid_x_m), 1e-12) << "step " << i;
    EXPECT_LT(std::abs(b[0].mean_vx_mps + b[1].mean_vx_mps), 1e-12) << "step " << i;
    EXPECT_LT(std::abs(b[0].centroid_y_m), 1e-12) << "step " << i;
    EXPECT_LT(b[0].mass_error, 0.01);
  }
  EXPECT_GT(engine.state().functionals.bodies[0].mean_vx_mps, 0.2);  // still flying at each other
}

TEST(Bodies, PenaltyStopsTwoBallsApartAndTheySeparate) {
  fsi::Scenario s = shipped("bodies/two_balls_collide.json");
  // 12 cm apart at the start, 2 cm outside the force's reach (dist_0 = 0.1 m).
  s.bodies[0].center_m.x = -0.31;
  s.bodies[1].center_m.x = 0.31;
  fsi::Engine engine(s);
  double min_gap = 1.0;
  bool apart = false;
  for (int i = 0; i < 400 && !apart; ++i) {
    const fsi::StepReport r = engine.step();
    ASSERT_TRUE(r.accepted && r.converged) << "step " << i << ": " << r.message;
    const auto& b = engine.state().functionals.bodies;
    EXPECT_LT(std::abs(b[0].centroid_x_m + b[1].centroid_x_m), 1e-12) << "step " << i;  // mirror-symmetric
    min_gap = std::min(min_gap, b[0].min_body_distance_m);
    apart = b[0].mean_vx_mps < -0.02 && b[1].mean_vx_mps > 0.02;
  }
  EXPECT_TRUE(apart) << "the balls did not turn round by t = " << engine.state().time_s << " s";
  // Stopped inside the force's reach and well clear of each other: more than half a
  // patch (2 cm), so that no patch holds both interfaces. tools/study-bodies compares
  // the gap with the force law's energy balance.
  EXPECT_LT(min_gap, 0.06);
  EXPECT_GT(min_gap, 0.01);
}

TEST(Bodies, ThreeBallsStartWithEachMassErrorUnderOnePercent) {
  fsi::Engine engine(shipped("three_balls.json"));
  for (int i = 0; i < 10; ++i) {
    const fsi::StepReport r = engine.step();
    ASSERT_TRUE(r.accepted && r.converged) << "step " << i << ": " << r.message;
  }
  const auto& b = engine.state().functionals.bodies;
  ASSERT_EQ(b.size(), 3u);
  for (std::size_t i = 0; i < b.size(); ++i) EXPECT_LT(b[i].mass_error, 0.01) << "body" << i + 1;
  EXPECT_GT(b[0].mean_vx_mps, 0.2);   // thrown right
  EXPECT_LT(b[2].mean_vx_mps, -0.1);  // thrown left
  EXPECT_LT(b[1].mean_vy_mps, -0.1);  // thrown down
}

TEST(Bodies, AnEllipseAndARoundedRectangleShareAScene) {
  fsi::Scenario s = shipped("bodies/two_balls_collide.json");
  s.bodies[0].shape = fsi::BodyShape::ellipse;
  s.bodies[0].half_size_m = {0.25, 0.15};
  s.bodies[0].angle_rad = 0.3;
  s.bodies[1].shape = fsi::BodyShape::rounded_rectangle;
  s.bodies[1].half_size_m = {0.2, 0.15};
  s.bodies[1].radius_m = 0.08;
  s.bodies[1].solid = fsi::SolidSpec{2000.0, 8e5, 3.2e6};
  fsi::Engine engine(s);
  for (int i = 0; i < 8; ++i) {
    const fsi::StepReport r = engine.step();
    ASSERT_TRUE(r.accepted && r.converged) << "step " << i << ": " << r.message;
  }
  const auto& b = engine.state().functionals.bodies;
  ASSERT_EQ(b.size(), 2u);
  // Each against its own shape's area (pi a b; 4 a b - (4 - pi) r^2).
  EXPECT_LT(b[0].mass_error, 0.02);
  EXPECT_LT(b[1].mass_error, 0.02);
  EXPECT_GT(b[0].mean_vx_mps, 0.1);  // still flying at each other
  EXPECT_LT(b[1].mean_vx_mps, -0.1);
}

TEST(Bodies, RestoredStateContinuesBitIdentically) {
  const fsi::Scenario s = shipped("bodies/two_balls_collide.json");
  fsi::Engine straight(s), first(s);
  for (int i = 0; i < 8; ++i) ASSERT_TRUE(straight.step().converged);
  for (int i = 0; i < 4; ++i) ASSERT_TRUE(first.step().converged);
  ASSERT_EQ(first.state().body_references.size(), 2u);
  EXPECT_GT(first.state().body_references[0].offset_x_m, 0.0);  // re-referenced as it moved
  const std::filesystem::path file = std::filesystem::path(FSI_BINARY_DIR) / "bodies_continue.ckpt";
  fsi::save_checkpoint(first, file);
  fsi::Engine resumed(s);
  fsi::load_checkpoint(resumed, file);
  for (int i = 0; i < 4; ++i) ASSERT_TRUE(resumed.step().converged);
  const Eigen::VectorXd& a = straight.state().solution;
  const Eigen::VectorXd& b = resumed.state().solution;
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(0, std::memcmp(a.data(), b.data(), sizeof(double) * a.size())) << "max diff " << (a - b).cwiseAbs().maxCoeff();
}

}  // namespace
