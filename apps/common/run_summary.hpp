#pragma once
/// \file run_summary.hpp
/// What a run did, collected step by step and written as summary.json:
///   scenario (name, source, fingerprint), steps, simulated and wall time, converged /
///   unconverged / rejected step counts, events (first occurrence of each kind with time,
///   place and count: real contact, active penalty contact, halved or rejected steps,
///   non-finite values), the minimal distance and when it occurred, the final
///   functionals, the outputs written, whether the run was interrupted (Ctrl-C) and
///   whether this is the final summary; and every touch-down on a wall ("contacts", and
///   the same on one line as "contact_sequence": "wall@time;wall@time..."), for the study
///   scripts: the engine reports real contact in every step the body touches a wall, a
///   touch-down is the first of a run of such steps on the same wall.
#include <filesystem>
#include <fsi/engine.hpp>
#include <fsi/scenario.hpp>
#include <map>
#include <set>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "earlier_run.hpp"

namespace fsi::app {

class RunSummary {
 public:
  explicit RunSummary(const Scenario& scenario);

  /// Records one step's report and the state it left.
  void record_step(const StepReport& report, const State& state);
  /// Takes over what an earlier run recorded up to its checkpoint (fsi-movie --continue):
  /// step counts, minimal distance and last functionals from its CSV rows, touch-downs
  /// and first events before the checkpoint from its summary. An event kind that began
  /// before the checkpoint keeps its first occurrence; its "steps" count then covers
  /// that occurrence and the steps after the checkpoint ("continued_from_step" says so).
  void continue_from(const EarlierRun& earlier);
  /// Records an output file or folder (listed relative to the summary's folder).
  void add_output(const std::filesystem::path& file);

  void set_interrupted(bool interrupted) { interrupted_ = interrupted; }
  /// Why the run ended before its end time (empty: it did not).
  void set_stop_reason(std::string why) { stop_reason_ = std::move(why); }
  const std::string& stop_reason() const { return stop_reason_; }

  bool interrupted() const { return interrupted_; }
  long steps() const { return steps_; }
  long unconverged_steps() const { return unconverged_; }
  long rejected_steps() const { return rejected_; }

  /// The summary. `is_final` (key "final"): false for the copies written after each
  /// frame while the run goes on (a killed run leaves one), true for the last one.
  nlohmann::ordered_json to_json(double wall_seconds, bool is_final,
                                 const std::filesystem::path& folder) const;
  /// Writes to_json to `file` (atomically: a temporary file renamed over it).
  void write(const std::filesystem::path& file, double wall_seconds, bool is_final) const;

 private:
  struct EventRecord {
    StepEvent first;
    long count = 0;
  };
  std::string name_, source_, fingerprint_;
  double end_time_s_;
  long steps_ = 0, unconverged_ = 0, rejected_ = 0;
  double time_s_ = 0.0;
  Functionals last_{};
  bool have_min_ = false;
  double min_distance_m_ = 0.0, min_distance_time_s_ = 0.0;
  std::map<StepEvent::Kind, EventRecord> events_;
  std::vector<StepEvent> touch_downs_;  ///< real-contact events that start a contact
  std::set<int> touching_walls_;        ///< walls touched in the latest step
  std::vector<std::filesystem::path> outputs_;
  bool interrupted_ = false;
  std::string stop_reason_;
  long continued_from_step_ = -1;  ///< -1: not a continued run
  /// Accepted steps by length [s], rounded to six digits (a continued run's lengths are
  /// differences of its CSV times): with numerics.time_step_max_doublings or halve_step they vary.
  std::map<double, long> step_lengths_;
  void count_step_length(double length_s);
};

}  // namespace fsi::app
