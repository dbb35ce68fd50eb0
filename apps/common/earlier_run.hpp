#pragma once
/// \file earlier_run.hpp
/// What an earlier fsi-movie run left in its folder, read so that `fsi-movie --continue`
/// can go on from its latest checkpoint as if it had never stopped: the rows of
/// functionals.csv up to that checkpoint (kept verbatim, and parsed for the plots) and
/// the earlier summary.json (touch-downs and first events before the checkpoint).
/// Long studies (the stairs take hours per run) survive a stopped machine this way.
#include <filesystem>
#include <fsi/output.hpp>
#include <fsi/state.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace fsi::app {

struct EarlierRun {
  std::filesystem::path checkpoint;  ///< the latest checkpoints/step_<n>.ckpt
  long step = 0;                     ///< n
  double time_s = 0.0;               ///< time of the row of step n
  std::vector<std::string> csv_rows;  ///< functionals.csv rows of steps 1..n, as written
  using Row = io::FunctionalsCsvRow;
  std::vector<Row> rows;          ///< the same rows, parsed
  nlohmann::json summary;         ///< summary.json (null if there is none)
};

/// Reads `out_dir`. Throws InputError naming the file when there is no checkpoint, no
/// functionals.csv with the newton columns, or the CSV lacks the checkpoint's step.
EarlierRun read_earlier_run(const std::filesystem::path& out_dir);

}  // namespace fsi::app
