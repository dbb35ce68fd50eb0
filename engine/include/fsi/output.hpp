#pragma once
/// \file output.hpp
/// Result files for ParaView/VisIt and spreadsheets, for apps and embedders:
///   - VTK XML (.vtu fields on the sub-triangles, .vtp interface lines) and a .pvd
///     time series rewritten after every frame;
///   - the chapter's functionals as CSV, one flushed row per time level.
///
///   fsi::io::PvdSeries series(out / "frames.pvd");
///   fsi::io::FunctionalsCsv csv(out / "functionals.csv", true);
///   for (...) {
///     const fsi::StepReport r = engine.step();
///     csv.append(engine.state(), r);
///     fsi::io::write_vtk_frame(out, "frame", engine.view(), series);
///   }
///
/// Every writer replaces or flushes its files so that a run that stops leaves valid
/// files behind. Implementations: engine/src/io/{vtu_writer,pvd_series,functionals_csv}.cpp.
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "fsi/engine.hpp"
#include "fsi/field_view.hpp"
#include "fsi/state.hpp"

namespace fsi::io {

// ---- ParaView time series (.pvd) ---------------------------------------------------

/// A ParaView time series: a .pvd collection file listing one dataset (or several
/// "parts") per time. It is rewritten, atomically, after every added frame, so it is a
/// valid file listing every frame written so far even if the run stops.
class PvdSeries {
 public:
  /// Starts an empty series in `pvd_file` (written at the first add()).
  explicit PvdSeries(std::filesystem::path pvd_file);

  /// Registers `dataset` (a path relative to the .pvd's folder) at `time_s` [s].
  /// `part` tells datasets of the same time apart (e.g. 0: fields, 1: interface).
  void add(double time_s, const std::filesystem::path& dataset, int part = 0);

  const std::filesystem::path& file() const { return file_; }
  std::size_t size() const { return entries_.size(); }

 private:
  struct Entry {
    double time_s;
    int part;
    std::string dataset;
  };
  std::filesystem::path file_;
  std::vector<Entry> entries_;
};

/// `text` with the five XML special characters escaped (for attribute values).
std::string xml_escaped(const std::string& text);

// ---- VTK XML files (.vtu, .vtp) ----------------------------------------------------
// FieldView -> VTK XML files (ASCII, values in shortest round-trip form, so they read
// back bit-identically):
//   .vtu  UnstructuredGrid: the sub-triangles; point data vx, vy, p, ux, uy and the
//         3-component vectors velocity and displacement; cell data phase (0 fluid,
//         1 solid); field data TimeValue.
//   .vtp  PolyData lines: the discrete interface (or any set of segments).
// Files are replaced atomically. A view whose arrays disagree in size, or whose
// triangles point past the nodes, is a programming error: std::invalid_argument.

/// Writes the mesh and nodal fields of `view` as a .vtu file.
void write_vtu(const std::filesystem::path& file, const FieldView& view);

/// Writes `segments` (e.g. view.interface) as a .vtp file of lines, time `time_s` [s].
void write_vtp_segments(const std::filesystem::path& file, const std::vector<Segment2>& segments,
                        double time_s);

/// One frame of a time series: writes `<folder>/<stem>_<step>.vtu` and
/// `<folder>/<stem>_interface_<step>.vtp` (step zero-padded to 6 digits) and adds them
/// to `series` (parts 0 and 1), whose .pvd should live in `folder`.
void write_vtk_frame(const std::filesystem::path& folder, const std::string& stem,
                     const FieldView& view, PvdSeries& series);

// ---- functionals as CSV ------------------------------------------------------------
// The time series of the chapter's functionals as CSV, one row per time level:
//   step,time_s,min_distance_m,bottom_y_m,top_y_m,left_x_m,right_x_m,centroid_x_m,
//   centroid_y_m,mean_vx_mps,mean_vy_mps,solid_area_m2,mass_error,cavitation_rate_m2ps
// ,rotation_rad, in a scene with several bodies each body's columns body<n>_centroid_x_m,
// body<n>_centroid_y_m, body<n>_mean_vx_mps, body<n>_mean_vy_mps, body<n>_min_distance_m,
// body<n>_min_body_distance_m, body<n>_mass_error, body<n>_rotation_rad (n = 1, 2, ...),
// plus, optionally, the step's solver report: newton_iterations,converged (0/1).
// Doubles are written in shortest round-trip form (full precision, reads back exactly);
// every row is flushed, so the file is usable while the run goes on or after it stops.

/// The header line (without newline); `bodies` > 1 adds each body's columns.
std::string functionals_csv_header(bool with_newton_columns, std::size_t bodies = 1);
/// True for the header line, or for that of files written before cavitation_rate_m2ps
/// existed (their rows read back with the rate 0).
bool is_functionals_csv_header(const std::string& line, bool with_newton_columns);

/// One data line (without newline). Without a report, only the functional columns.
std::string functionals_csv_row(long step, double time_s, const Functionals& functionals);

/// One row of a functionals CSV with the newton columns, read back (e.g. to continue a
/// run; a row of a file without cavitation_rate_m2ps reads with it 0). Throws
/// std::invalid_argument on a cell that is not a number or a wrong count.
struct FunctionalsCsvRow {
  long step = 0;
  double time_s = 0.0;
  Functionals functionals;
  int newton_iterations = 0;
  bool converged = false;
};
FunctionalsCsvRow parse_functionals_csv_row(const std::string& line);
/// The row again, in this version's columns.
std::string functionals_csv_row(const FunctionalsCsvRow& row);
std::string functionals_csv_row(long step, double time_s, const Functionals& functionals,
                                const StepReport& report);

class FunctionalsCsv {
 public:
  /// Creates (or truncates) `file` and writes the header. `with_newton_columns` adds
  /// newton_iterations and converged; rows must then come with a StepReport.
  /// Throws InputError if the file cannot be opened.
  FunctionalsCsv(const std::filesystem::path& file, bool with_newton_columns, std::size_t bodies = 1);
  /// The same, then `first_rows` (rows of an earlier run that this one continues,
  /// written as they are).
  FunctionalsCsv(const std::filesystem::path& file, bool with_newton_columns,
                 const std::vector<std::string>& first_rows, std::size_t bodies = 1);

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
