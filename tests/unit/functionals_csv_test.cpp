#include "fsi/output.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fsi/error.hpp"
#include "io_test_support.hpp"

namespace {

namespace fs = std::filesystem;

fs::path temp_file(const std::string& name) {
  return fsi::test::scratch_dir("functionals_csv") / name;
}

std::vector<std::string> lines(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> result;
  for (std::string line; std::getline(in, line);) result.push_back(line);
  return result;
}

std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> result;
  std::stringstream s(line);
  for (std::string cell; std::getline(s, cell, ',');) result.push_back(cell);
  return result;
}

fsi::State sample_state() {
  fsi::State s;
  s.step = 42;
  s.time_s = 0.084;
  s.functionals = {1.0 / 3.0, -0.6, 0.4, -0.41, 0.41, 1e-17, -0.2, -3e-5, -0.25, 0.502, 2e-7, 3.5e-4, 0.0, {}};
  return s;
}

TEST(FunctionalsCsv, RowsReadBackExactly) {
  const fsi::State s = sample_state();
  fsi::StepReport report;
  report.newton_iterations = 7;
  report.converged = false;
  const fsi::io::FunctionalsCsvRow r =
      fsi::io::parse_functionals_csv_row(fsi::io::functionals_csv_row(s.step, s.time_s, s.functionals, report));
  EXPECT_EQ(r.step, 42);
  EXPECT_EQ(r.time_s, 0.084);
  EXPECT_EQ(r.functionals.min_distance_m, 1.0 / 3.0);
  EXPECT_EQ(r.functionals.mean_vx_mps, s.functionals.mean_vx_mps);
  EXPECT_EQ(r.functionals.mean_vy_mps, s.functionals.mean_vy_mps);
  EXPECT_EQ(r.functionals.mass_error, 2e-7);
  EXPECT_EQ(r.functionals.cavitation_rate_m2ps, 3.5e-4);
  EXPECT_EQ(r.newton_iterations, 7);
  EXPECT_FALSE(r.converged);
  EXPECT_THROW(fsi::io::parse_functionals_csv_row("1,2,x"), std::invalid_argument);
  EXPECT_THROW(fsi::io::parse_functionals_csv_row("1,2,3"), std::invalid_argument);
}

TEST(FunctionalsCsv, HeaderNamesEveryColumn) {
  EXPECT_EQ(fsi::io::functionals_csv_header(false),
            "step,time_s,min_distance_m,bottom_y_m,top_y_m,left_x_m,right_x_m,centroid_x_m,"
            "centroid_y_m,mean_vx_mps,mean_vy_mps,solid_area_m2,mass_error,cavitation_rate_m2ps,rotation_rad");
  EXPECT_EQ(cells(fsi::io::functionals_csv_header(true)).size(), 17u);
}

// Runs written before the cavitation column (the oldest runs) must still continue: their
// header is accepted and their rows read with the rate 0, and written back in today's columns.
TEST(FunctionalsCsv, FilesWithoutTheCavitationColumnReadBack) {
  const std::string old_header =
      "step,time_s,min_distance_m,bottom_y_m,top_y_m,left_x_m,right_x_m,centroid_x_m,"
      "centroid_y_m,mean_vx_mps,mean_vy_mps,solid_area_m2,mass_error,newton_iterations,converged";
  EXPECT_TRUE(fsi::io::is_functionals_csv_header(old_header, true));
  EXPECT_TRUE(fsi::io::is_functionals_csv_header(fsi::io::functionals_csv_header(true), true));
  EXPECT_FALSE(fsi::io::is_functionals_csv_header(old_header, false));
  EXPECT_FALSE(fsi::io::is_functionals_csv_header("step,time_s", true));
  const fsi::io::FunctionalsCsvRow r =
      fsi::io::parse_functionals_csv_row("3,0.006,0.5,-0.5,0.3,-0.4,0.4,0,-0.1,0,-0.01,0.5,0.007,4,1");
  EXPECT_EQ(r.step, 3);
  EXPECT_EQ(r.functionals.mass_error, 0.007);
  EXPECT_EQ(r.functionals.cavitation_rate_m2ps, 0.0);
  EXPECT_EQ(r.newton_iterations, 4);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(fsi::io::functionals_csv_row(r), "3,0.006,0.5,-0.5,0.3,-0.4,0.4,0,-0.1,0,-0.01,0.5,0.007,0,0,4,1");
  // One column short of every layout.
  EXPECT_THROW(fsi::io::parse_functionals_csv_row("3,0.006,0.5,-0.5,0.3,-0.4,0.4,0,-0.1,0,-0.01,0.5,4,1"),
               std::invalid_argument);
}

// Runs written before the rotation column (with the cavitation column) continue too:
// their rows read with the rotation 0.
TEST(FunctionalsCsv, FilesWithoutTheRotationColumnReadBack) {
  const std::string header =
      "step,time_s,min_distance_m,bottom_y_m,top_y_m,left_x_m,right_x_m,centroid_x_m,"
      "centroid_y_m,mean_vx_mps,mean_vy_mps,solid_area_m2,mass_error,cavitation_rate_m2ps,newton_iterations,converged";
  EXPECT_TRUE(fsi::io::is_functionals_csv_header(header, true));
  const fsi::io::FunctionalsCsvRow r =
      fsi::io::parse_functionals_csv_row("3,0.006,0.5,-0.5,0.3,-0.4,0.4,0,-0.1,0,-0.01,0.5,0.007,2e-4,4,1");
  EXPECT_EQ(r.functionals.cavitation_rate_m2ps, 2e-4);
  EXPECT_EQ(r.functionals.rotation_rad, 0.0);
  EXPECT_EQ(r.newton_iterations, 4);
  EXPECT_EQ(fsi::io::functionals_csv_row(r), "3,0.006,0.5,-0.5,0.3,-0.4,0.4,0,-0.1,0,-0.01,0.5,0.007,2e-04,0,4,1");
}

TEST(FunctionalsCsv, RowsReadBackExactlyInHeaderOrder) {
  const fs::path file = temp_file("plain.csv");
  const fsi::State s = sample_state();
  {
    fsi::io::FunctionalsCsv csv(file, false);
    csv.append(s);
    // Flushed per row: readable before the writer closes.
    EXPECT_EQ(lines(file).size(), 2u);
  }
  const auto all = lines(file);
  ASSERT_EQ(all.size(), 2u);
  const auto header = cells(all[0]);
  const auto row = cells(all[1]);
  ASSERT_EQ(row.size(), header.size());
  EXPECT_EQ(row[0], "42");
  const fsi::Functionals& f = s.functionals;
  const std::vector<double> expected{s.time_s,       f.min_distance_m, f.bottom_y_m,
                                     f.top_y_m,      f.left_x_m,       f.right_x_m,
                                     f.centroid_x_m, f.centroid_y_m,   f.mean_vx_mps,
                                     f.mean_vy_mps,  f.solid_area_m2,  f.mass_error,
                                     f.cavitation_rate_m2ps};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(std::strtod(row[i + 1].c_str(), nullptr), expected[i]) << header[i + 1];
  }
  EXPECT_EQ(header[9], "mean_vx_mps");
  EXPECT_EQ(row[9], "-0.25");  // mean_vx (the struct stores mean_vy first): not swapped
}

TEST(FunctionalsCsv, NewtonColumnsComeFromTheStepReport) {
  const fs::path file = temp_file("newton.csv");
  fsi::StepReport report;
  report.newton_iterations = 5;
  report.converged = false;
  {
    fsi::io::FunctionalsCsv csv(file, true);
    csv.append(sample_state(), report);
    report.converged = true;
    csv.append(sample_state(), report);
    EXPECT_THROW(csv.append(sample_state()), std::logic_error);
  }
  const auto all = lines(file);
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(cells(all[1]).size(), 17u);
  EXPECT_EQ(all[1].substr(all[1].size() - 4), ",5,0");
  EXPECT_EQ(all[2].substr(all[2].size() - 4), ",5,1");

  fsi::io::FunctionalsCsv plain(temp_file("plain2.csv"), false);
  EXPECT_THROW(plain.append(sample_state(), report), std::logic_error);
}

TEST(FunctionalsCsv, ReportsAnUnwritableFile) {
  fsi::test::expect_input_error(
      [] { fsi::io::FunctionalsCsv csv("/nonexistent/dir/f.csv", false); },
      {"/nonexistent/dir/f.csv", "cannot open for writing"});
}

}  // namespace
