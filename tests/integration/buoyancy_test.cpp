// Buoyancy (Scenario::buoyancy): the solid feels (rho_s - rho_f) g and the fluid no
// gravity. A body of the fluid's density then floats, a lighter one rises and a denser one
// sinks, each starting with the acceleration of a cylinder with its added mass,
// (rho_s - rho_f) g / (rho_s + rho_f). Without buoyancy (the chapter) every body sinks.
#include <fsi/engine.hpp>
#include <gtest/gtest.h>

#include <cmath>

#include "test_scenarios.hpp"

namespace {

/// The coarse Example 1 with the given solid density [kg/m^3], away from the ground.
fsi::Scenario ball_of_density(double rho_s_kgpm3, bool buoyancy) {
  fsi::Scenario s = fsi::testing::coarse_example1(fsi::Method::fsi);
  s.solid.density_kgpm3 = rho_s_kgpm3;
  s.buoyancy = buoyancy;
  s.gravity_mps2 = {0.0, -1.0};
  s.numerics.time_step_s = 5e-3;
  return s;
}

/// The body's mean vertical velocity [m/s] after `steps` steps, every one converged.
double vy_after(const fsi::Scenario& s, int steps) {
  fsi::Engine engine(s);
  for (int i = 0; i < steps; ++i) {
    const fsi::StepReport r = engine.step();
    EXPECT_TRUE(r.accepted && r.converged) << "step " << i << ": " << r.message;
  }
  return engine.state().functionals.mean_vy_mps;
}

TEST(Buoyancy, BodyOfTheFluidsDensityFloats) {
  // 0.1 s: without buoyancy it would be falling at about 0.05 m/s.
  const double vy = vy_after(ball_of_density(1000.0, true), 20);
  EXPECT_LT(std::abs(vy), 1e-4) << vy;
}

TEST(Buoyancy, LighterRisesDenserSinksWithTheirAddedMass) {
  const double t_s = 0.1;  // 20 steps of 5e-3 s, before the flow's drag matters much
  const double g = 1.0;
  for (double rho_s : {500.0, 2000.0}) {
    const double vy = vy_after(ball_of_density(rho_s, true), 20);
    const double expected = -(rho_s - 1000.0) * g / (rho_s + 1000.0) * t_s;  // 1/3 g t
    EXPECT_NEAR(vy, expected, 0.2 * std::abs(expected)) << "rho_s " << rho_s;
  }
}

TEST(Buoyancy, OffTheBodyOfTheFluidsDensitySinks) {
  // The chapter's model: the solid carries rho_s g, the fluid nothing (g / 2 with the
  // added mass of a body of the fluid's density).
  const double vy = vy_after(ball_of_density(1000.0, false), 20);
  EXPECT_NEAR(vy, -0.5 * 1.0 * 0.1, 0.2 * 0.05) << vy;
}

TEST(Buoyancy, IsPartOfTheFingerprintOnlyWhenOn) {
  const fsi::Scenario off = fsi::example1_scenario();
  fsi::Scenario on = off;
  on.buoyancy = true;
  EXPECT_NE(fsi::fingerprint(on), fsi::fingerprint(off));
  const fsi::Scenario back = fsi::parse_scenario(fsi::to_json(on), "<test>");
  EXPECT_TRUE(back.buoyancy);
  EXPECT_EQ(fsi::fingerprint(back), fsi::fingerprint(on));
}

}  // namespace
