// A ball landing on a tread's edge without a contact force (tests/data/tread_edge_landing.json:
// campaign seed 5's case 38 started 1.2 cm from the edge, moving at 0.38 m/s, 0.36 m/s of it
// towards the edge). Without the corner barrier (contact.corner_barrier_speed_mps = 0) it
// touches the edge, holds on to its no-slip node and is turned inside out at t = 0.06 s
// (step 36). With it the edge stops and deflects the ball before it touches
// (core/corner_barrier.hpp, docs/method.md "Corner barrier").
#include <fsi/engine.hpp>
#include <gtest/gtest.h>

#include <filesystem>

namespace {

TEST(TreadEdgeLanding, TheEdgeStopsTheBallBeforeItTouches) {
  const fsi::Scenario s =
      fsi::load_scenario(std::filesystem::path(FSI_SOURCE_DIR) / "tests" / "data" / "tread_edge_landing.json");
  ASSERT_EQ(s.contact.gamma_c, 0.0) << "no contact force: the barrier alone";
  fsi::Engine engine(s);
  const Eigen::Vector2d towards_edge = -Eigen::Vector2d(0.6786, 0.7346);  // from the ball to the edge
  const auto approach_mps = [&] {
    const fsi::Functionals& f = engine.state().functionals;
    return Eigen::Vector2d(f.mean_vx_mps, f.mean_vy_mps).dot(towards_edge);
  };
  while (engine.state().time_s < s.numerics.end_time_s - 1e-9) {
    const fsi::StepReport r = engine.step();
    ASSERT_TRUE(r.converged) << "t = " << engine.state().time_s << ": " << r.message;
    for (const fsi::StepEvent& e : r.events) ASSERT_NE(e.kind, fsi::StepEvent::Kind::real_contact) << e.text;
    ASSERT_GT(engine.state().functionals.min_distance_m, 5e-3) << "t = " << engine.state().time_s;
  }
  EXPECT_LT(approach_mps(), 0.5 * 0.36) << "the edge has taken more than half the approach speed";
  EXPECT_LT(engine.state().functionals.mass_error, 0.02);
}

}  // namespace
