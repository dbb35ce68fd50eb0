// The fsi-movie run loop: step, record, and every n-th step a frame in every format.
#include "movie_run.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <fsi/engine.hpp>
#include <fsi/error.hpp>
#include <fsi/output.hpp>
#include <fsi/png.hpp>
#include <memory>
#include <optional>
#ifdef FSI_RENDER_HAS_VIDEO
#include <fsi/video.hpp>
#endif

#include "functional_plots.hpp"
#include "interrupt_flag.hpp"
#include "movie_color_range.hpp"
#include "progress_meter.hpp"
#include "run_summary.hpp"
#include "scenario_overrides.hpp"

namespace fsi::app {
namespace {

namespace fs = std::filesystem;

/// A discrete body that lost (or gained) half its mass is no longer a simulation of
/// the scenario (it happens only after a failed step near a wall): stop instead of
/// spending hours on it. Normal runs stay below 1e-2.
constexpr double kLostBodyMassError = 0.5;


class MovieRun {
 public:
  MovieRun(const Scenario& scenario, const MovieOptions& options)
      : options_(options),
        engine_(scenario),
        summary_(scenario),
        earlier_(options.continue_run ? std::optional(read_earlier_run(options.out_dir)) : std::nullopt),
        csv_(options.out_dir / "functionals.csv", /*with_newton_columns=*/true,
             earlier_ ? earlier_->csv_rows : std::vector<std::string>{}, scene_bodies(scenario).size()),
        pvd_(options.out_dir / "vtk" / "frames.pvd"),
        meter_(0.0, scenario.numerics.end_time_s, options.quiet) {
    if (earlier_) options_.resume_from = earlier_->checkpoint;
    if (!options_.resume_from.empty()) {
      load_checkpoint(engine_, options_.resume_from);
      meter_ = ProgressMeter(engine_.state().time_s, scenario.numerics.end_time_s, options.quiet);
    }
    if (earlier_) last_checkpoint_step_ = engine_.state().step;  // its checkpoint is in out_dir
    if (options.checkpoint_every > 0) fs::create_directories(options.out_dir / "checkpoints");
    const OutputSpec& out = scenario.output;
    spec_.width = out.width_px;
    spec_.height = out.height_px;
    spec_.quantity = render::parse_quantity(out.field);
    spec_.show_mesh = out.mesh_overlay;
    spec_.window = options.zoom;
    spec_.keep_aspect = !options.stretch;
    spec_.title = scenario.name;
    spec_.range = movie_color_range(scenario, spec_.quantity, engine_.view());
    if (options.second_field) {
      spec_.second_quantity = options.second_field;
      spec_.second_range = movie_color_range(scenario, *options.second_field, engine_.view());
    }
    summary_.add_output(options.out_dir / "functionals.csv");
    // The scenario the run uses, --set overrides applied (fsi-movie scenario.json OUT2
    // repeats the run; the study scripts read its parameters).
    write_scenario_file(scenario, (options.out_dir / "scenario.json").string());
    summary_.add_output(options.out_dir / "scenario.json");
    if (options.png) fs::create_directories(options.out_dir / "frames");
    if (options.vtu) fs::create_directories(options.out_dir / "vtk");
#ifdef FSI_RENDER_HAS_VIDEO
    if (options.video) {
      render::VideoOptions vo;
      vo.fps = out.fps;
      video_.emplace(options.out_dir / "movie.mp4", spec_.width, spec_.height, vo);
      summary_.add_output(options.out_dir / "movie.mp4");
    }
#else
    if (options.video)
      meter_.note("fsi-movie: built without video (FSI_WITH_VIDEO=OFF): no movie.mp4");
#endif
    if (earlier_) {
      summary_.continue_from(*earlier_);
      for (const EarlierRun::Row& r : earlier_->rows) history_.add(r.time_s, r.functionals);
    } else {
      history_.add(engine_.state().time_s, engine_.state().functionals);
    }
  }

  MovieResult run() {
    const Scenario& s = engine_.scenario();
    // Frames at equal intervals of simulated time, so that a movie plays at one speed when
    // steps vary in length (time_step_max_doublings, halved steps): every frame_every-th step at
    // a constant k.
    const double frame_interval_s = s.output.frame_every * s.numerics.time_step_s;
    const auto frame_index = [&](double t) {
      return static_cast<long>(std::floor((t + 0.5 * s.numerics.time_step_s) / frame_interval_s));
    };
    long last_frame_index = frame_index(engine_.state().time_s);
    write_frame();
    // Whether the state the loop stops at is worth continuing from (checkpointed below).
    bool resumable_stop = false;
    bool broken_state = false;  // no frame of it
    for (;;) {
      if (interrupt_requested()) {
        summary_.set_interrupted(true);
        summary_.set_stop_reason("interrupted by a signal");
        resumable_stop = true;
        break;
      }
      // Half a step of slack: t accumulates rounding, t = end - 1e-16 is the end.
      if (engine_.state().time_s >= s.numerics.end_time_s - 0.5 * s.numerics.time_step_s) {
        resumable_stop = true;
        break;
      }
      const StepReport r = engine_.step();
      const State& st = engine_.state();
      summary_.record_step(r, st);
      if (!r.converged) {
        char where[96];
        std::snprintf(where, sizeof where, "warning: step %ld (t = %.6g s): ", st.step, st.time_s);
        meter_.note(where + r.message);
      }
      if (!r.accepted) {
        // The engine rolled the step back: the state is the last good one, and it is
        // what the checkpoint and the last frame below show.
        char where[64];
        std::snprintf(where, sizeof where, "step %ld (t = %.6g s): ", st.step + 1, st.time_s);
        summary_.set_stop_reason(std::string("the engine rejected ") + where + r.message);
        resumable_stop = true;
        break;
      }
      csv_.append(st, r);
      history_.add(st.time_s, st.functionals);
      if (!(st.functionals.mass_error <= kLostBodyMassError)) {
        char why[160];
        std::snprintf(why, sizeof why,
                      "the body degenerated at t = %.6g s (relative mass error %.3g > %.2g): stopped",
                      st.time_s, st.functionals.mass_error, kLostBodyMassError);
        meter_.note(std::string("fsi-movie: ") + why);
        summary_.set_stop_reason(why);
        broken_state = true;
        break;
      }
      if (const long i = frame_index(st.time_s); i > last_frame_index) {
        last_frame_index = i;
        write_frame();
      }
      if (options_.checkpoint_every > 0 && st.step % options_.checkpoint_every == 0)
        write_checkpoint(st.step);
      meter_.update(st.time_s, st.step, summary_.unconverged_steps());
    }
    // A killed study run then continues where it stopped instead of up to
    // checkpoint_every steps (hours, for the stairs) earlier.
    if (resumable_stop && options_.checkpoint_every > 0 && engine_.state().step != last_checkpoint_step_)
      write_checkpoint(engine_.state().step);
    if (!broken_state && engine_.state().step != last_frame_step_) write_frame();  // the last state
    meter_.finish();
    finish_outputs();
    return {summary_.interrupted(), summary_.steps(), summary_.unconverged_steps(), wall_seconds(),
            summary_.stop_reason()};
  }

 private:
  double wall_seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

  void write_frame() {
    const FieldView view = engine_.view();
    last_frame_step_ = view.step;
    char name[48];
    std::snprintf(name, sizeof name, "frame_%06ld.png", view.step);
    // Only what is written gets made: no picture for a --no-png --no-video run, no
    // PNG encoding for a video-only one. The image's storage is reused frame to frame.
    if (options_.png || video_active()) {
      if (options_.film_inset) spec_.inset = render::film_window(view);
      renderer_.render(view, spec_, image_);
      if (options_.png) render::write_png(options_.out_dir / "frames" / name, image_);
#ifdef FSI_RENDER_HAS_VIDEO
      if (video_) video_->write(image_);
#endif
    }
    if (options_.vtu) io::write_vtk_frame(options_.out_dir / "vtk", "frame", view, pvd_);
    if (options_.png) summary_.add_output(options_.out_dir / "frames");
    if (options_.vtu) summary_.add_output(pvd_.file());
    summary_.write(options_.out_dir / "summary.json", wall_seconds(), false);
  }

  void write_checkpoint(long step) {
    char name[48];
    std::snprintf(name, sizeof name, "step_%06ld.ckpt", step);
    save_checkpoint(engine_, options_.out_dir / "checkpoints" / name);
    last_checkpoint_step_ = step;
  }

  bool video_active() const {
#ifdef FSI_RENDER_HAS_VIDEO
    return video_.has_value();
#else
    return false;
#endif
  }

  // Closes the video, draws the plots, writes the final summary.
  void finish_outputs() {
#ifdef FSI_RENDER_HAS_VIDEO
    if (video_) video_->close();
#endif
    try {
      for (const fs::path& f :
           write_functional_plots(renderer_, history_, engine_.scenario().name, options_.out_dir))
        summary_.add_output(f);
    } catch (const std::exception& e) {
      meter_.note(std::string("warning: plots not written: ") + e.what());
    }
    summary_.write(options_.out_dir / "summary.json", wall_seconds(), true);
  }

  MovieOptions options_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  Engine engine_;
  RunSummary summary_;
  std::optional<EarlierRun> earlier_;  ///< what the continued run left (continue_run)
  io::FunctionalsCsv csv_;
  io::PvdSeries pvd_;
  ProgressMeter meter_;
  FunctionalsHistory history_;
  render::Renderer renderer_;
  render::FrameSpec spec_;
  render::Image image_;  ///< the latest frame, its storage reused
#ifdef FSI_RENDER_HAS_VIDEO
  std::optional<render::VideoWriter> video_;
#endif
  long last_frame_step_ = -1;
  long last_checkpoint_step_ = -1;
};

}  // namespace

MovieResult run_movie(const Scenario& scenario, const MovieOptions& options) {
  fs::create_directories(options.out_dir);
  MovieRun run(scenario, options);
  return run.run();
}

}  // namespace fsi::app
