// Functionals as CSV. The column order is the header's; keep both in one place (here).
#include "fsi/output.hpp"

#include <iterator>
#include <utility>
#include <stdexcept>
#include <vector>

#include "fsi/error.hpp"
#include "io/number_text.hpp"

namespace fsi::io {

namespace {

/// The columns every version wrote; files written before the cavitation column existed
/// end here, those written before the rotation column after cavitation_rate_m2ps, and
/// both still read back (continued runs).
constexpr const char* kCommonHeader =
    "step,time_s,min_distance_m,bottom_y_m,top_y_m,left_x_m,right_x_m,centroid_x_m,"
    "centroid_y_m,mean_vx_mps,mean_vy_mps,solid_area_m2,mass_error";
constexpr const char* kCavitationHeader = ",cavitation_rate_m2ps";
constexpr const char* kNewtonHeader = ",newton_iterations,converged";

/// The functionals in the header's order (after step and time_s).
constexpr double Functionals::*kColumns[] = {
    &Functionals::min_distance_m, &Functionals::bottom_y_m,   &Functionals::top_y_m,
    &Functionals::left_x_m,       &Functionals::right_x_m,    &Functionals::centroid_x_m,
    &Functionals::centroid_y_m,   &Functionals::mean_vx_mps,  &Functionals::mean_vy_mps,
    &Functionals::solid_area_m2,  &Functionals::mass_error, &Functionals::cavitation_rate_m2ps,
    &Functionals::rotation_rad};
/// The functionals of the older files: without cavitation_rate_m2ps and rotation_rad, and
/// without rotation_rad.
constexpr std::size_t kOlderColumns[] = {std::size(kColumns) - 2, std::size(kColumns) - 1};

/// Each body's columns in a scene with several, named body<n>_<name>.
constexpr std::pair<const char*, double Functionals::Body::*> kBodyColumns[] = {
    {"centroid_x_m", &Functionals::Body::centroid_x_m},
    {"centroid_y_m", &Functionals::Body::centroid_y_m},
    {"mean_vx_mps", &Functionals::Body::mean_vx_mps},
    {"mean_vy_mps", &Functionals::Body::mean_vy_mps},
    {"min_distance_m", &Functionals::Body::min_distance_m},
    {"min_body_distance_m", &Functionals::Body::min_body_distance_m},
    {"mass_error", &Functionals::Body::mass_error},
    {"rotation_rad", &Functionals::Body::rotation_rad}};

/// Scenes have at most this many bodies (io::kMaxBodies).
constexpr std::size_t kMaxBodyColumns = 8;

}  // namespace

std::string functionals_csv_header(bool with_newton_columns, std::size_t bodies) {
  std::string h = std::string(kCommonHeader) + kCavitationHeader + ",rotation_rad";
  for (std::size_t b = 1; bodies > 1 && b <= bodies; ++b)
    for (const auto& [name, member] : kBodyColumns) h.append(",body").append(std::to_string(b)).append("_").append(name);
  if (with_newton_columns) h += kNewtonHeader;
  return h;
}

bool is_functionals_csv_header(const std::string& line, bool with_newton_columns) {
  const std::string newton = with_newton_columns ? kNewtonHeader : "";
  for (std::size_t bodies = 1; bodies <= kMaxBodyColumns; ++bodies)
    if (line == functionals_csv_header(with_newton_columns, bodies)) return true;
  return line == std::string(kCommonHeader) + newton || line == std::string(kCommonHeader) + kCavitationHeader + newton;
}

std::string functionals_csv_row(long step, double time_s, const Functionals& f) {
  std::string row = std::to_string(step);
  row.append(",").append(number_text(time_s));
  for (double Functionals::*column : kColumns) row.append(",").append(number_text(f.*column));
  for (const Functionals::Body& b : f.bodies)
    for (const auto& [name, member] : kBodyColumns) row.append(",").append(number_text(b.*member));
  return row;
}

FunctionalsCsvRow parse_functionals_csv_row(const std::string& line) {
  std::vector<double> v;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t end = line.find(',', begin);
    const std::string cell = line.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
    std::size_t used = 0;
    try {
      v.push_back(std::stod(cell, &used));
    } catch (const std::exception&) {
      used = std::string::npos;
    }
    if (used != cell.size()) throw std::invalid_argument("not a number: '" + cell + "'");
    if (end == std::string::npos) break;
    begin = end + 1;
  }
  constexpr std::size_t kWithNewton = 2 + std::size(kColumns) + 2;
  const bool older = v.size() == 2 + kOlderColumns[0] + 2 || v.size() == 2 + kOlderColumns[1] + 2;
  // Several bodies: their columns between the scene's and the newton columns.
  const std::size_t body_cells = v.size() > kWithNewton ? v.size() - kWithNewton : 0;
  const std::size_t bodies = body_cells / std::size(kBodyColumns);
  const bool with_bodies = body_cells > 0 && body_cells % std::size(kBodyColumns) == 0 && bodies >= 2 &&
                           bodies <= kMaxBodyColumns;
  if (v.size() != kWithNewton && !older && !with_bodies) {
    throw std::invalid_argument("expected " + std::to_string(kWithNewton) + " columns (or " +
                                std::to_string(2 + kOlderColumns[0] + 2) + " and " +
                                std::to_string(2 + kOlderColumns[1] + 2) + " in files written before " +
                                "cavitation_rate_m2ps and rotation_rad), got " + std::to_string(v.size()));
  }
  FunctionalsCsvRow r;
  r.step = static_cast<long>(v[0]);
  r.time_s = v[1];
  const std::size_t columns = v.size() - 4 - body_cells;
  for (std::size_t i = 0; i < columns; ++i) r.functionals.*kColumns[i] = v[2 + i];
  if (with_bodies) {
    r.functionals.bodies.resize(bodies);
    std::size_t cell = 2 + columns;
    for (Functionals::Body& b : r.functionals.bodies)
      for (const auto& [name, member] : kBodyColumns) b.*member = v[cell++];
  }
  r.newton_iterations = static_cast<int>(v[v.size() - 2]);
  r.converged = v[v.size() - 1] != 0.0;
  return r;
}

std::string functionals_csv_row(const FunctionalsCsvRow& row) {
  return functionals_csv_row(row.step, row.time_s, row.functionals) + "," +
         std::to_string(row.newton_iterations) + (row.converged ? ",1" : ",0");
}

std::string functionals_csv_row(long step, double time_s, const Functionals& f,
                                const StepReport& report) {
  return functionals_csv_row({step, time_s, f, report.newton_iterations, report.converged});
}

FunctionalsCsv::FunctionalsCsv(const std::filesystem::path& file, bool with_newton_columns, std::size_t bodies)
    : file_(file), with_newton_(with_newton_columns), out_(file, std::ios::trunc) {
  if (!out_) throw InputError(file.string(), "", "cannot open for writing");
  write_line(functionals_csv_header(with_newton_, bodies));
}

FunctionalsCsv::FunctionalsCsv(const std::filesystem::path& file, bool with_newton_columns,
                               const std::vector<std::string>& first_rows, std::size_t bodies)
    : FunctionalsCsv(file, with_newton_columns, bodies) {
  for (const std::string& row : first_rows) write_line(row);
}

void FunctionalsCsv::append(const State& state) {
  if (with_newton_) {
    throw std::logic_error("FunctionalsCsv: this file has newton columns; pass the StepReport");
  }
  write_line(functionals_csv_row(state.step, state.time_s, state.functionals));
}

void FunctionalsCsv::append(const State& state, const StepReport& report) {
  if (!with_newton_) {
    throw std::logic_error("FunctionalsCsv: this file has no newton columns");
  }
  write_line(functionals_csv_row(state.step, state.time_s, state.functionals, report));
}

void FunctionalsCsv::write_line(const std::string& line) {
  out_ << line << '\n';
  out_.flush();  // a stopped run leaves every finished row on disk
  if (!out_) throw InputError(file_.string(), "", "write failed");
}

}  // namespace fsi::io
