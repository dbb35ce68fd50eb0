// Reading back an earlier run's folder for fsi-movie --continue (see the header).
#include "earlier_run.hpp"

#include <fstream>
#include <regex>
#include <stdexcept>

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

}  // namespace

EarlierRun read_earlier_run(const fs::path& out_dir) {
  EarlierRun e;
  e.checkpoint = latest_checkpoint(out_dir, e.step);
  const fs::path csv = out_dir / "functionals.csv";
  std::ifstream in(csv);
  if (!in) throw InputError(csv.string(), "", "cannot read the earlier run's functionals");
  std::string line;
  if (!std::getline(in, line) || !io::is_functionals_csv_header(line, true)) {
    throw InputError(csv.string(), "header", "not an fsi-movie functionals file with newton columns");
  }
  // Rows of an older file (without the cavitation or rotation column) are rewritten in today's
  // columns, so that the continued file has one header.
  const bool older_columns = line != io::functionals_csv_header(true);
  bool found = false;
  for (std::size_t line_no = 2; std::getline(in, line); ++line_no) {
    if (line.empty()) continue;
    EarlierRun::Row r;
    try {
      r = io::parse_functionals_csv_row(line);
    } catch (const std::invalid_argument& why) {
      throw InputError(csv.string(), "line " + std::to_string(line_no), why.what());
    }
    if (r.step > e.step) break;
    e.csv_rows.push_back(older_columns ? io::functionals_csv_row(r) : line);
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
