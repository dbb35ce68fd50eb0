// The functional cavitation_rate_m2ps: the fluid area the cavitation floor creates per
// second, int_F ramp(p_cav - p) / mu_f dx. With a prescribed uniform pressure below the
// floor it is the fluid's area times the deficit over mu_f; it is 0 above the floor and
// with the floor off.
#include <fsi/engine.hpp>
#include <gtest/gtest.h>

#include "test_scenarios.hpp"

namespace {

/// The functional after setting the pressure to `p_pa` at every node.
double rate_at_uniform_pressure(double cavitation_pressure_pa, double p_pa, double* fluid_area_m2 = nullptr) {
  fsi::Scenario s = fsi::testing::coarse_example1();
  s.numerics.cavitation_pressure_pa = cavitation_pressure_pa;
  fsi::Engine engine(s);
  fsi::State state = engine.state();
  for (Eigen::Index n = 0; n < state.solution.size() / fsi::kFieldsPerNode; ++n)
    state.solution[fsi::kFieldsPerNode * n + fsi::kP] = p_pa;
  engine.set_state(state);
  const double domain_area_m2 = 2.0 * 1.5;  // [-1, 1] x [-1, 0.5]
  if (fluid_area_m2) *fluid_area_m2 = domain_area_m2 - engine.state().functionals.solid_area_m2;
  return engine.state().functionals.cavitation_rate_m2ps;
}

TEST(CavitationRate, IsTheFluidAreaTimesTheDeficitOverMu) {
  const fsi::Scenario s = fsi::testing::coarse_example1();
  const double mu_f = s.fluid.density_kgpm3 * s.fluid.viscosity_m2ps;
  double fluid_area = 0.0;
  // 1e4 Pa below the floor: beyond the rounding (a quarter of |p_cav| wide), so the ramp is exact.
  const double rate = rate_at_uniform_pressure(-1e4, -2e4, &fluid_area);
  EXPECT_GT(fluid_area, 2.0);
  EXPECT_NEAR(rate, fluid_area * 1e4 / mu_f, 1e-9 * rate);
}

TEST(CavitationRate, IsZeroAboveTheFloorAndWithTheFloorOff) {
  EXPECT_EQ(rate_at_uniform_pressure(-1e4, -5e3), 0.0);
  EXPECT_EQ(rate_at_uniform_pressure(0.0, -2e4), 0.0);
  EXPECT_GT(rate_at_uniform_pressure(-1e4, -1e4), 0.0);  // inside the rounding: small, not 0
}

TEST(CavitationRate, StaysZeroInAFallWithoutSuction) {
  fsi::Scenario s = fsi::testing::coarse_example1();
  s.numerics.cavitation_pressure_pa = -1e4;
  fsi::Engine engine(s);
  for (int i = 0; i < 3; ++i) engine.step();
  EXPECT_EQ(engine.state().functionals.cavitation_rate_m2ps, 0.0);
}

}  // namespace
