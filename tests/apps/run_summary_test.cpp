// summary.json's touch-downs: the engine reports real contact in every step the body
// touches a wall; the study scripts need one entry per touch-down, wall by wall.
#include <gtest/gtest.h>

#include <vector>

#include "run_summary.hpp"
#include "test_scenarios.hpp"

namespace {

fsi::StepReport touching(const std::vector<int>& walls, double t) {
  fsi::StepReport r;
  r.accepted = r.converged = true;
  for (int w : walls)
    r.events.push_back({fsi::StepEvent::Kind::real_contact, t, {0.5, -1.0}, w, "real contact"});
  return r;
}

TEST(RunSummary, ListsEveryTouchDownOnce) {
  const fsi::Scenario s = fsi::testing::coarse_example1();
  fsi::app::RunSummary summary(s);
  fsi::State state;
  const std::vector<std::pair<std::vector<int>, double>> steps{
      {{}, 0.1}, {{0}, 0.2}, {{0}, 0.3}, {{}, 0.4}, {{0}, 0.5}, {{0, 3}, 0.6}, {{3}, 0.7}, {{}, 0.8}};
  for (const auto& [walls, t] : steps) {
    state.time_s = t;
    summary.record_step(touching(walls, t), state);
  }
  const auto j = summary.to_json(1.0, true, ".");
  EXPECT_EQ(j["contact_sequence"], "0@0.2000;0@0.5000;3@0.6000");
  ASSERT_EQ(j["contacts"].size(), 3u);
  EXPECT_EQ(j["contacts"][2]["wall"], 3);
  EXPECT_DOUBLE_EQ(j["contacts"][1]["time_s"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(j["contacts"][0]["where_m"][0].get<double>(), 0.5);
}

}  // namespace
