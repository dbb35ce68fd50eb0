// Functionals as CSV. The column order is the header's; keep both in one place (here).
#include "fsi/output.hpp"

#include <stdexcept>

#include "fsi/error.hpp"
#include "io/number_text.hpp"

namespace fsi::io {

std::string functionals_csv_header(bool with_newton_columns) {
  std::string h =
      "step,time_s,min_distance_m,bottom_y_m,top_y_m,left_x_m,right_x_m,centroid_x_m,"
      "centroid_y_m,mean_vx_mps,mean_vy_mps,solid_area_m2,mass_error";
  if (with_newton_columns) h += ",newton_iterations,converged";
  return h;
}

std::string functionals_csv_row(long step, double time_s, const Functionals& f) {
  std::string row = std::to_string(step);
  for (double v :
       {time_s, f.min_distance_m, f.bottom_y_m, f.top_y_m, f.left_x_m, f.right_x_m, f.centroid_x_m,
        f.centroid_y_m, f.mean_vx_mps, f.mean_vy_mps, f.solid_area_m2, f.mass_error}) {
    row.append(",").append(number_text(v));
  }
  return row;
}

std::string functionals_csv_row(long step, double time_s, const Functionals& f,
                                const StepReport& report) {
  return functionals_csv_row(step, time_s, f) + "," + std::to_string(report.newton_iterations) +
         (report.converged ? ",1" : ",0");
}

FunctionalsCsv::FunctionalsCsv(const std::filesystem::path& file, bool with_newton_columns)
    : file_(file), with_newton_(with_newton_columns), out_(file, std::ios::trunc) {
  if (!out_) throw InputError(file.string(), "", "cannot open for writing");
  write_line(functionals_csv_header(with_newton_));
}

FunctionalsCsv::FunctionalsCsv(const std::filesystem::path& file, bool with_newton_columns,
                               const std::vector<std::string>& first_rows)
    : FunctionalsCsv(file, with_newton_columns) {
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
