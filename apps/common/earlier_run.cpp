// Reading back an earlier run's folder for fsi-movie --continue (see the header).
#include "earlier_run.hpp"

#include <fstream>
#include <regex>
#include <sstream>

#include <fsi/error.hpp>
#include <fsi/output.hpp>

namespace fsi::app {
namespace fs = std::filesystem;
namespace {

/// The checkpoint with the largest step in out_dir/checkpoints.
fs::path latest_checkpoint(const fs::path& out_dir, long& step) {
  const fs::path dir = out_dir / "checkpoints";
  const std::regex name(R"(step_(\d+)\.ckpt)");
  fs::path best;
  step = -1;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    std::smatch m;
    const std::string file = e.path().filename().string();
    if (!std::regex_match(file, m, name)) continue;
    const long s = std::stol(m[1].str());
    if (s > step) {
      step = s;
      best = e.path();
    }
  }
  if (best.empty()) {
    throw InputError(dir.string(), "", "no checkpoint (step_<n>.ckpt) to continue from; "
                                       "the earlier run needs --checkpoint-every");
  }
  return best;
}

EarlierRun::Row parse_row(const std::string& line, const fs::path& file, std::size_t line_no) {
  std::vector<double> v;
  std::stringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ',')) {
    try {
      v.push_back(std::stod(cell));
    } catch (const std::exception&) {
      throw InputError(file.string(), "line " + std::to_string(line_no), "not a number: '" + cell + "'");
    }
  }
  if (v.size() != 15) {
    throw InputError(file.string(), "line " + std::to_string(line_no),
                     "expected 15 columns, got " + std::to_string(v.size()));
  }
  EarlierRun::Row r{};
  r.step = static_cast<long>(v[0]);
  r.time_s = v[1];
  Functionals& f = r.functionals;
  f.min_distance_m = v[2];
  f.bottom_y_m = v[3];
  f.top_y_m = v[4];
  f.left_x_m = v[5];
  f.right_x_m = v[6];
  f.centroid_x_m = v[7];
  f.centroid_y_m = v[8];
  f.mean_vx_mps = v[9];
  f.mean_vy_mps = v[10];
  f.solid_area_m2 = v[11];
  f.mass_error = v[12];
  r.converged = v[14] != 0.0;
  return r;
}

}  // namespace

EarlierRun read_earlier_run(const fs::path& out_dir) {
  EarlierRun e;
  e.checkpoint = latest_checkpoint(out_dir, e.step);
  const fs::path csv = out_dir / "functionals.csv";
  std::ifstream in(csv);
  if (!in) throw InputError(csv.string(), "", "cannot read the earlier run's functionals");
  std::string line;
  if (!std::getline(in, line) || line != io::functionals_csv_header(true)) {
    throw InputError(csv.string(), "header", "not an fsi-movie functionals file with newton columns");
  }
  bool found = false;
  for (std::size_t line_no = 2; std::getline(in, line); ++line_no) {
    if (line.empty()) continue;
    const EarlierRun::Row r = parse_row(line, csv, line_no);
    if (r.step > e.step) break;
    e.csv_rows.push_back(line);
    e.rows.push_back(r);
    if (r.step == e.step) {
      e.time_s = r.time_s;
      found = true;
    }
  }
  if (!found) {
    throw InputError(csv.string(), "step " + std::to_string(e.step),
                     "has no row for the step of " + e.checkpoint.filename().string());
  }
  const fs::path summary = out_dir / "summary.json";
  if (std::ifstream s(summary); s) {
    e.summary = nlohmann::json::parse(s, nullptr, /*allow_exceptions=*/false);
    if (e.summary.is_discarded()) throw InputError(summary.string(), "", "not valid JSON");
  }
  return e;
}

}  // namespace fsi::app
