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

TEST(RunSummary, ContinuedRunKeepsTheTouchDownsBeforeItsCheckpoint) {
  const fsi::Scenario s = fsi::testing::coarse_example1();
  // What a stopped run left: touch-downs at 0.2 s (wall 2) and 0.6 s (wall 4), a
  // checkpoint at 0.4 s while still touching wall 2 (distance 0).
  fsi::app::RunSummary earlier_summary(s);
  fsi::State state;
  for (const auto& [walls, t] : std::vector<std::pair<std::vector<int>, double>>{
           {{}, 0.1}, {{2}, 0.2}, {{2}, 0.3}, {{2}, 0.4}, {{}, 0.5}, {{4}, 0.6}}) {
    state.time_s = t;
    earlier_summary.record_step(touching(walls, t), state);
  }
  fsi::app::EarlierRun earlier;
  earlier.step = 4;
  earlier.time_s = 0.4;
  earlier.summary = nlohmann::json::parse(earlier_summary.to_json(1.0, false, ".").dump());
  for (int i = 1; i <= 4; ++i) {
    fsi::app::EarlierRun::Row r{};
    r.step = i;
    r.time_s = 0.1 * i;
    r.functionals.min_distance_m = i >= 2 ? 0.0 : 0.01;
    r.converged = i != 3;
    earlier.rows.push_back(r);
  }

  fsi::app::RunSummary summary(s);
  summary.continue_from(earlier);
  // The continued run: still on wall 2 at 0.5 s (not a new touch-down), then wall 4.
  for (const auto& [walls, t] : std::vector<std::pair<std::vector<int>, double>>{
           {{2}, 0.5}, {{}, 0.6}, {{4}, 0.7}}) {
    state.time_s = t;
    summary.record_step(touching(walls, t), state);
  }
  const auto j = summary.to_json(1.0, true, ".");
  EXPECT_EQ(j["contact_sequence"], "2@0.2000;4@0.7000");
  EXPECT_EQ(j["steps"], 7);
  EXPECT_EQ(j["unconverged_steps"], 1);
  EXPECT_EQ(j["continued_from_step"], 4);
  EXPECT_DOUBLE_EQ(j["min_distance"]["time_s"].get<double>(), 0.2);
}

TEST(RunSummary, CountsStepsByLength) {
  // Steps of 1e-3, 8e-3 (longer, away from the walls) and 5e-4 (halved); the earlier
  // run's lengths come from its CSV times, which carry rounding.
  const fsi::Scenario s = fsi::testing::coarse_example1();
  fsi::app::EarlierRun earlier;
  earlier.step = 3;
  double t = 0.0;
  for (int i = 1; i <= 3; ++i) {
    fsi::app::EarlierRun::Row r{};
    r.step = i;
    t += i == 2 ? 8e-3 : 1e-3;
    r.time_s = t;
    r.converged = true;
    earlier.rows.push_back(r);
  }
  earlier.time_s = t;
  fsi::app::RunSummary summary(s);
  summary.continue_from(earlier);
  fsi::State state;
  for (double k : {5e-4, 1e-3, 8e-3}) {
    fsi::StepReport r = touching({}, t += k);
    r.time_step_s = k;
    state.time_s = t;
    summary.record_step(r, state);
  }
  fsi::StepReport rejected = touching({}, t);
  rejected.accepted = false;
  rejected.time_step_s = 1.25e-4;
  summary.record_step(rejected, state);
  const auto j = summary.to_json(1.0, true, ".");
  ASSERT_EQ(j["step_lengths"].size(), 3u) << j["step_lengths"].dump();
  EXPECT_DOUBLE_EQ(j["step_lengths"][0]["length_s"].get<double>(), 5e-4);
  EXPECT_EQ(j["step_lengths"][0]["steps"], 1);
  EXPECT_DOUBLE_EQ(j["step_lengths"][1]["length_s"].get<double>(), 1e-3);
  EXPECT_EQ(j["step_lengths"][1]["steps"], 3);
  EXPECT_DOUBLE_EQ(j["step_lengths"][2]["length_s"].get<double>(), 8e-3);
  EXPECT_EQ(j["step_lengths"][2]["steps"], 2);
}

}  // namespace
