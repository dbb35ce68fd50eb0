#pragma once
/// \file progress_meter.hpp
/// Progress of a run on stderr. On a terminal a bar rewritten in place,
///   [#########...........] t=1.234/5.000 s step 617 ETA 2m13s
/// otherwise (a log file, CI) a plain line every 10% of the simulated time or every
/// 30 s of wall time. Messages printed through note() never get mixed into the bar.
#include <chrono>
#include <cstdio>
#include <string>

namespace fsi::app {

class ProgressMeter {
 public:
  /// `start_s`, `end_s`: simulated time span [s]. `quiet`: print nothing but note()s.
  /// The terminal check is isatty(fileno(out)).
  ProgressMeter(double start_s, double end_s, bool quiet, std::FILE* out = stderr);

  /// The run reached simulated time `t_s` after step `step`; `unconverged` steps so far.
  void update(double t_s, long step, long unconverged);
  /// A line of its own (warnings), printed even when quiet.
  void note(const std::string& line);
  /// Ends the bar's line.
  void finish();

  /// "2m13s", "1h02m", "45s" for a duration [s].
  static std::string duration_text(double seconds);

 private:
  void clear_bar();

  double start_s_, end_s_;
  bool quiet_, terminal_;
  std::FILE* out_;
  bool bar_shown_ = false;
  std::chrono::steady_clock::time_point wall_start_, last_print_;
  int last_decile_ = 0;
};

}  // namespace fsi::app
