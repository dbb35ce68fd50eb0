// Restoring a state and stepping on is bit-identical to stepping straight through,
// including the reuse of the LU factorization across steps (FactorizationOrigin).
#include <fsi/engine.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>

#include <fsi/error.hpp>

#include "test_scenarios.hpp"

namespace {

/// `before` steps, a checkpoint, `after` steps against `before + after` straight.
void expect_restored_state_continues_bit_identically(const fsi::Scenario& s, int before = 4, int after = 4) {
  fsi::Engine straight(s);
  for (int i = 0; i < before + after; ++i) ASSERT_TRUE(straight.step().converged);

  fsi::Engine first(s);
  for (int i = 0; i < before; ++i) ASSERT_TRUE(first.step().converged);
  // Through a checkpoint file, as a user would; one file per test, since CTest runs the
  // tests of this file in parallel processes.
  const std::filesystem::path file =
      std::filesystem::path(FSI_BINARY_DIR) /
      (std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".ckpt");
  fsi::save_checkpoint(first, file);
  fsi::Engine resumed(s);
  fsi::load_checkpoint(resumed, file);
  for (int i = 0; i < after; ++i) ASSERT_TRUE(resumed.step().converged);

  const Eigen::VectorXd& a = straight.state().solution;
  const Eigen::VectorXd& b = resumed.state().solution;
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(0, std::memcmp(a.data(), b.data(), sizeof(double) * a.size())) << "max diff " << (a - b).cwiseAbs().maxCoeff();
  EXPECT_EQ(straight.state().time_s, resumed.state().time_s);
  EXPECT_EQ(straight.state().corner_sign, resumed.state().corner_sign);
  EXPECT_EQ(straight.state().edge_cut, resumed.state().edge_cut);
}

TEST(Determinism, RestoredStateContinuesBitIdentically) {
  expect_restored_state_continues_bit_identically(fsi::testing::coarse_example1());
}

TEST(Determinism, RestoredStateContinuesBitIdenticallyWithLongerSteps) {
  // The next step's length comes from the state's functionals and the controller's
  // limit (time_step_max_doublings): a restored state must choose it as the uninterrupted run
  // did. After one step (k) the limit is 2k although 4k would be allowed otherwise.
  fsi::Scenario s = fsi::testing::coarse_example1();
  s.numerics.time_step_s = 5e-3;
  s.numerics.time_step_max_doublings = 2;  // up to 2e-2 s
  expect_restored_state_continues_bit_identically(s, 1, 3);
}

TEST(Determinism, RestoredStateContinuesBitIdenticallyWithErrorControlAndThreeThreads) {
  // The error-controlled step limit is part of the state (time_step_limit_s); the element
  // loops on three threads sum in the fixed colour order.
  fsi::Scenario s = fsi::testing::coarse_example1();
  s.numerics.time_step_s = 5e-3;
  s.numerics.time_step_max_doublings = 2;  // up to 2e-2 s
  s.numerics.time_error_tolerance_m = 1e-6;
  s.numerics.assembly_threads = 3;
  expect_restored_state_continues_bit_identically(s, 3, 3);
}

TEST(Determinism, AssemblyThreadsGiveTheSameBits) {
  fsi::Scenario s = fsi::testing::coarse_example1();
  s.numerics.assembly_threads = 1;
  fsi::Engine one(s);
  s.numerics.assembly_threads = 3;
  fsi::Engine three(s);
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(one.step().converged);
    ASSERT_TRUE(three.step().converged);
  }
  const Eigen::VectorXd& x = one.state().solution;
  const Eigen::VectorXd& y = three.state().solution;
  ASSERT_EQ(x.size(), y.size());
  EXPECT_EQ(0, std::memcmp(x.data(), y.data(), sizeof(double) * x.size())) << "max diff " << (x - y).cwiseAbs().maxCoeff();
}

TEST(Determinism, RestoredStateContinuesBitIdenticallyWithGmres) {
  // With GMRES the norm's row scale comes from each step's own start, so only the
  // factorization (the preconditioner) has to be restored.
  fsi::Scenario s = fsi::testing::coarse_example1();
  s.numerics.krylov_iterations = 40;
  expect_restored_state_continues_bit_identically(s);
}

TEST(Determinism, RestoredStateContinuesBitIdenticallyAfterAMovingStart) {
  // A moving start (the potential flow, the first step without the cavitation floor, the
  // second from p = 0: Engine::Impl::set_step_rules) goes on bit for bit from a
  // checkpoint after its first step.
  fsi::Scenario s = fsi::testing::coarse_example1(fsi::Method::fsi);
  s.walls = {fsi::Segment2{{-1.0, 0.5}, {-1.0, -1.0}}, fsi::Segment2{{-1.0, -1.0}, {1.0, -1.0}},
             fsi::Segment2{{1.0, -1.0}, {1.0, 0.5}}};
  s.body.initial_velocity_mps = {1.0, 0.0};  // an impulse of about +-5e4 Pa: under the floor
  s.numerics.time_step_s = 2e-3;
  expect_restored_state_continues_bit_identically(s, 1, 3);
}

TEST(Determinism, RestoredStateContinuesBitIdenticallyInRealContact) {
  // The ball touches the ground at step 20 and springs back: the wall's hold on the solid
  // (core/contact_release.hpp, from the residual at each step's start) goes on bit for
  // bit from a checkpoint taken in contact.
  expect_restored_state_continues_bit_identically(fsi::testing::stiff_ball_touching_down(), 26, 8);
}

TEST(Determinism, RestoredStateContinuesBitIdenticallyAfterReReferencing) {
  // The reference is part of the state and of the checkpoint (format 6); the factorization
  // origin keeps the reference of its own step.
  const fsi::Scenario s = fsi::testing::coarse_example1();
  fsi::Engine straight(s), first(s);
  for (fsi::Engine* e : {&straight, &first}) {
    for (int i = 0; i < 3; ++i) ASSERT_TRUE(e->step().converged);
    e->rereference();
  }
  const std::filesystem::path file = std::filesystem::path(FSI_BINARY_DIR) / "rereferenced.ckpt";
  fsi::save_checkpoint(first, file);
  fsi::Engine resumed(s);
  fsi::load_checkpoint(resumed, file);
  EXPECT_EQ(resumed.state().reference_offset_y_m, first.state().reference_offset_y_m);
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(straight.step().converged);
    ASSERT_TRUE(resumed.step().converged);
  }
  const Eigen::VectorXd& a = straight.state().solution;
  const Eigen::VectorXd& b = resumed.state().solution;
  EXPECT_EQ(0, std::memcmp(a.data(), b.data(), sizeof(double) * a.size())) << "max diff " << (a - b).cwiseAbs().maxCoeff();
}

TEST(Determinism, ReReferencingDoesNotChangeTheMotion) {
  const fsi::Scenario s = fsi::testing::coarse_example1();
  fsi::Engine plain(s), moved(s);
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(plain.step().converged);
    ASSERT_TRUE(moved.step().converged);
  }
  const fsi::Functionals before = moved.state().functionals;
  moved.rereference();
  // The falling ball's reference went down with it; the interface did not move.
  EXPECT_LT(moved.state().reference_offset_y_m, -1e-5);
  EXPECT_NEAR(moved.state().reference_offset_y_m, before.centroid_y_m - s.body.center_m.y, 1e-3);
  EXPECT_EQ(moved.state().corner_sign, plain.state().corner_sign);
  EXPECT_NEAR(moved.state().functionals.bottom_y_m, before.bottom_y_m, 1e-12);
  for (int i = 0; i < 4; ++i) {
    ASSERT_TRUE(plain.step().converged);
    ASSERT_TRUE(moved.step().converged);
  }
  EXPECT_NEAR(moved.state().functionals.centroid_y_m, plain.state().functionals.centroid_y_m, 1e-8);
  EXPECT_NEAR(moved.state().functionals.mean_vy_mps, plain.state().functionals.mean_vy_mps, 1e-7);
  EXPECT_NEAR(moved.state().functionals.mass_error, plain.state().functionals.mass_error, 1e-7);
}

TEST(Determinism, CheckpointOfAnotherScenarioIsRefused) {
  fsi::Scenario s = fsi::testing::coarse_example1();
  fsi::Engine a(s);
  a.step();
  const std::filesystem::path file = std::filesystem::path(FSI_BINARY_DIR) / "other.ckpt";
  fsi::save_checkpoint(a, file);
  s.solid.mu_pa *= 2;
  fsi::Engine b(s);
  try {
    fsi::load_checkpoint(b, file);
    FAIL() << "a checkpoint of another scenario was accepted";
  } catch (const fsi::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("fingerprint"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
}

TEST(Determinism, TwoRunsAreBitIdentical) {
  const fsi::Scenario s = fsi::testing::coarse_example1();
  fsi::Engine a(s), b(s);
  for (int i = 0; i < 3; ++i) {
    a.step();
    b.step();
  }
  const Eigen::VectorXd& x = a.state().solution;
  const Eigen::VectorXd& y = b.state().solution;
  EXPECT_EQ(0, std::memcmp(x.data(), y.data(), sizeof(double) * x.size()));
}

}  // namespace
