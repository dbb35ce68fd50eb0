// --set on a whole scenario (apps/common/scenario_overrides.hpp): /method switches the
// numerics still at the old preset's values, the renamed step-limit keys still work.
#include <gtest/gtest.h>

#include <string>

#include "fsi/error.hpp"
#include "scenario_overrides.hpp"

namespace {

using fsi::app::apply_overrides;
using fsi::app::parse_override;

TEST(ScenarioOverrides, MethodSwitchesThePresetAndKeepsWhatWasSet) {
  fsi::Scenario base = fsi::example1_scenario();
  base.numerics.time_step_s = 5e-4;
  base.numerics.time_step_max_doublings = 2;        // set on purpose: stays
  base.numerics.cavitation_pressure_pa = -3e4;      // set on purpose: stays
  const fsi::Scenario s = apply_overrides(base, {parse_override("/method=chapter")}, "test");
  EXPECT_EQ(s.method, fsi::Method::chapter);
  EXPECT_EQ(s.numerics.time_step_s, 5e-4);
  EXPECT_EQ(s.numerics.time_step_max_doublings, 2);
  EXPECT_EQ(s.numerics.cavitation_pressure_pa, -3e4);
  // At the fsi preset's values: now the chapter's.
  EXPECT_EQ(s.numerics.time_step_wall_zone_doublings, 0);
  EXPECT_EQ(s.numerics.backflow_beta, 0.0);
  EXPECT_EQ(s.numerics.newton_budget, 8);
  EXPECT_EQ(s.numerics.newton_rel_tol, 1e-8);
  // A --set after it goes on top.
  const fsi::Scenario t = apply_overrides(
      base, {parse_override("/method=chapter"), parse_override("/numerics/backflow_beta=1")}, "test");
  EXPECT_EQ(t.numerics.backflow_beta, 1.0);
  // And back: the chapter's values become the fsi preset's.
  const fsi::Scenario back = apply_overrides(s, {parse_override("/method=fsi")}, "test");
  EXPECT_EQ(back.numerics.backflow_beta, 1.0);
  EXPECT_EQ(back.numerics.newton_budget, 12);
  EXPECT_EQ(back.numerics.time_step_max_doublings, 2);
}

TEST(ScenarioOverrides, BadMethodNamesTheKey) {
  try {
    apply_overrides(fsi::example1_scenario(), {parse_override("/method=book")}, "test with --set");
    ADD_FAILURE() << "no error";
  } catch (const fsi::InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("/method"), std::string::npos) << what;
    EXPECT_NE(what.find("\"fsi\", \"chapter\""), std::string::npos) << what;
  }
}

TEST(ScenarioOverrides, OldStepLimitKeysSetTheDoublings) {
  fsi::Scenario base = fsi::example1_scenario();  // k = 2e-3 s, 3 doublings
  const fsi::Scenario s = apply_overrides(
      base, {parse_override("/numerics/time_step_max_s=4e-3"), parse_override("/numerics/time_step_wall_zone_max_s=0")},
      "test");
  EXPECT_EQ(s.numerics.time_step_max_doublings, 1);
  EXPECT_EQ(s.numerics.time_step_wall_zone_doublings, 0);
}

}  // namespace
