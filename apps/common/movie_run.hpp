#pragma once
/// \file movie_run.hpp
/// The batch run behind fsi-movie: steps a scenario to its end time and writes, into
/// one folder,
///   frames/frame_<step>.png   a picture every frame_every-th step (and of the last state)
///   movie.mp4                 the same pictures as H.264, one fixed colour range
///   functionals.csv           every step, with newton_iterations and converged
///   plot_{distance,height,velocity,mass}.png   the functionals over time
///   vtk/frame_<step>.vtu, vtk/frame_interface_<step>.vtp, vtk/frames.pvd
///   summary.json              see run_summary.hpp
/// It stops early, cleanly (files closed, plots and summary written), on SIGINT/SIGTERM
/// or when the engine rejects a step.
#include <filesystem>
#include <fsi/renderer.hpp>
#include <fsi/scenario.hpp>
#include <optional>

namespace fsi::app {

struct MovieOptions {
  std::filesystem::path out_dir;
  /// The picture: size, field, mesh overlay, frame rate and frame_every come from the
  /// scenario's output section (the app's options override it there).
  std::optional<render::ViewWindow> zoom;  ///< unset: the whole domain
  bool video = true;
  bool png = true;
  bool vtu = true;
  bool quiet = false;  ///< no progress output (warnings still go to stderr)
};

/// How the run ended.
struct MovieResult {
  bool interrupted = false;
  long steps = 0;
  long unconverged_steps = 0;
  double wall_seconds = 0.0;
};

/// Runs `scenario` as described above. Throws on unusable output folders or files.
MovieResult run_movie(const Scenario& scenario, const MovieOptions& options);

}  // namespace fsi::app
