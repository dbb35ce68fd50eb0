#pragma once
/// \file movie_run.hpp
/// The batch run behind fsi-movie: steps a scenario to its end time and writes, into
/// one folder,
///   frames/frame_<step>.png   a picture every frame_every x time_step_s of simulated time
///                             (every frame_every-th step at a constant k; and of the last state)
///   movie.mp4                 the same pictures as H.264, one fixed colour range
///   functionals.csv           every step, with newton_iterations and converged
///   plot_{distance,height,velocity,mass}.png   the functionals over time
///   vtk/frame_<step>.vtu, vtk/frame_interface_<step>.vtp, vtk/frames.pvd
///   summary.json              see run_summary.hpp
///   checkpoints/step_<step>.ckpt   with checkpoint_every > 0 (and of the last state)
/// It stops early, cleanly (files closed, plots and summary written), on SIGINT/SIGTERM
/// when the engine rejects a step, or when the body degenerates (mass error > 50%).
#include <filesystem>
#include <fsi/renderer.hpp>
#include <fsi/scenario.hpp>
#include <optional>
#include <string>

namespace fsi::app {

struct MovieOptions {
  std::filesystem::path out_dir;
  /// The picture: size, field, mesh overlay, frame rate and frame_every come from the
  /// scenario's output section (the app's options override it there).
  std::optional<render::ViewWindow> zoom;  ///< unset: the whole domain
  bool stretch = false;  ///< the window fills the picture (x, y scaled apart)
  /// A second field in a panel right of the first (e.g. p next to the velocity), with
  /// its own fixed colour range (movie_color_range.hpp); unset = one panel.
  std::optional<render::Quantity> second_field;
  /// Near contact, an inset magnifying the film between the body and the floor
  /// (render::film_window, recomputed per frame; absent while the gap is wide).
  bool film_inset = false;
  bool video = true;
  bool png = true;
  bool vtu = true;
  bool quiet = false;  ///< no progress output (warnings still go to stderr)
  /// Start from this checkpoint (written by save_checkpoint for the same scenario)
  /// instead of t = 0; the outputs then cover the resumed part only.
  std::filesystem::path resume_from;
  /// Continue the run in out_dir from its latest checkpoint: functionals.csv keeps the
  /// earlier rows up to it, summary.json its touch-downs and events (earlier_run.hpp).
  /// Excludes resume_from.
  bool continue_run = false;
  /// Write checkpoints/step_<step>.ckpt every this many steps (0: never), so that a
  /// long run can be resumed or a late event re-run from a nearby state. With it on,
  /// the last state is checkpointed too when the run reaches its end time or is stopped
  /// by a signal, so that --continue loses no steps (not after a rejected step or a
  /// degenerated body: continuing from there would only fail again).
  long checkpoint_every = 0;
};

/// How the run ended.
struct MovieResult {
  bool interrupted = false;
  long steps = 0;
  long unconverged_steps = 0;
  double wall_seconds = 0.0;
  /// Why the run ended before its end time (a rejected step, a degenerated body; also
  /// "interrupted by a signal"), as in summary.json; empty when it reached the end.
  std::string stop_reason;
};

/// Runs `scenario` as described above. Throws on unusable output folders or files.
MovieResult run_movie(const Scenario& scenario, const MovieOptions& options);

}  // namespace fsi::app
