// The first steps of the stairs (Example 2) on a coarse mesh (tests/data/stairs_coarse.json,
// made by tools/make-stairs-scenarios): the multi-block mesh with its inclined plane runs,
// Newton converges, and the ball starts to fall.
#include <fsi/engine.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace {

TEST(StairsShort, BallFallsTowardsThePlane) {
  const fsi::Scenario s =
      fsi::load_scenario(std::filesystem::path(FSI_SOURCE_DIR) / "tests" / "data" / "stairs_coarse.json");
  fsi::Engine engine(s);
  const fsi::Functionals f0 = engine.state().functionals;
  EXPECT_NEAR(f0.bottom_y_m, s.body.center_m.y - s.body.radius_m, 0.01);
  double previous_vy = 0.0;
  for (int i = 0; i < 8; ++i) {
    const fsi::StepReport r = engine.step();
    ASSERT_TRUE(r.converged) << "step " << i << ": " << r.message;
    ASSERT_TRUE(engine.state().solution.allFinite());
    const fsi::Functionals& f = engine.state().functionals;
    EXPECT_LT(f.mean_vy_mps, previous_vy) << "step " << i << ": still accelerating downwards";
    previous_vy = f.mean_vy_mps;
    for (const fsi::StepEvent& e : r.events)
      EXPECT_NE(e.kind, fsi::StepEvent::Kind::real_contact) << "the ball is far from every wall";
  }
  const fsi::Functionals& f = engine.state().functionals;
  // About a g t^2 / 2 with a ~ g / 2 (added mass of the fluid): 0.4 mm after 0.08 s.
  EXPECT_LT(f.centroid_y_m, f0.centroid_y_m - 2e-4);
  EXPECT_LT(f.bottom_y_m, f0.bottom_y_m - 2e-4);
  EXPECT_LT(f.min_distance_m, f0.min_distance_m);
  EXPECT_LT(f.mass_error, 0.03);
  // Nothing pushes it sideways yet: the plane is still 0.45 m away.
  EXPECT_LT(std::abs(f.mean_vx_mps), 0.1 * std::abs(f.mean_vy_mps));
}

}  // namespace
