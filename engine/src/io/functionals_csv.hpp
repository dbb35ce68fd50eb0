#pragma once
/// \file functionals_csv.hpp
/// The time series of the chapter's functionals as CSV, one row per time level:
///   step,time_s,min_distance_m,bottom_y_m,top_y_m,left_x_m,right_x_m,centroid_x_m,
///   centroid_y_m,mean_vx_mps,mean_vy_mps,solid_area_m2,mass_error
/// plus, optionally, the step's solver report: newton_iterations,converged (0/1).
/// Doubles are written in shortest round-trip form (full precision, reads back exactly);
/// every row is flushed, so the file is usable while the run goes on or after it stops.
#include <filesystem>
#include <fstream>
#include <string>

#include "fsi/engine.hpp"
#include "fsi/state.hpp"

namespace fsi::io {

/// The header line (without newline).
std::string functionals_csv_header(bool with_newton_columns);

/// One data line (without newline). Without a report, only the functional columns.
std::string functionals_csv_row(long step, double time_s, const Functionals& functionals);
std::string functionals_csv_row(long step, double time_s, const Functionals& functionals,
                                const StepReport& report);

class FunctionalsCsv {
 public:
  /// Creates (or truncates) `file` and writes the header. `with_newton_columns` adds
  /// newton_iterations and converged; rows must then come with a StepReport.
  /// Throws InputError if the file cannot be opened.
  FunctionalsCsv(const std::filesystem::path& file, bool with_newton_columns);

  /// Appends the functionals of `state` (its step and time). Only without newton columns.
  void append(const State& state);
  /// Appends the functionals of `state` and the report of the step that produced it.
  /// Only with newton columns.
  void append(const State& state, const StepReport& report);

  bool with_newton_columns() const { return with_newton_; }

 private:
  void write_line(const std::string& line);

  std::filesystem::path file_;
  bool with_newton_;
  std::ofstream out_;
};

}  // namespace fsi::io
