// fsi-movie: runs a scenario to its end time and writes pictures, a movie, the
// functionals, plots, VTK files and a run summary into one folder (see
// apps/common/movie_run.hpp for the folder's contents).
//
//   fsi-movie SCENARIO.json OUTDIR [--set KEY=VALUE ...] [--frame-every N]
//             [--field vx|vy|vmag|p|umag] [--no-video] [--no-png] [--no-vtu] [--size WxH]
//             [--fps N] [--zoom x0,y0,x1,y1 [--stretch]] [--mesh] [--end-time T] [--quiet]
//             [--checkpoint-every N] [--resume CHECKPOINT | --continue]
//             [--second-field vx|vy|vmag|p|umag] [--film-inset]
//
// --set changes one scenario key (a path into the scenario's JSON, the value as JSON)
// before the scenario is validated; --frame-every, --field, --size, --fps, --mesh and
// --end-time are shorthands for --set on /output/... and /numerics/end_time_s.
// --stretch lets the zoom window fill the picture, x and y scaled apart (the axes say
// by how much): a film 1 mm high under a ball 0.8 m wide becomes readable.
// --second-field adds a panel with a second field right of the first (velocity and
// pressure side by side); --film-inset shows, near contact, an inset that magnifies the
// film between the ball and the floor.
// --checkpoint-every N writes OUTDIR/checkpoints/step_<step>.ckpt every N steps;
// --resume starts from such a checkpoint (same scenario, same --set changes) instead of
// t = 0, e.g. to re-run the seconds around a contact with other outputs (the outputs
// then cover the resumed part only). --continue goes on with the run in OUTDIR from its
// latest checkpoint (a stopped or finished run, e.g. with a later --end-time):
// functionals.csv keeps its rows up to that checkpoint and summary.json its touch-downs.
// Progress goes to stderr (a bar on a terminal). Ctrl-C stops after the current step,
// closes the movie and writes the plots and summary.json with "interrupted": true.
// Exit code: 0 done, 1 failed while running (also a run the engine stopped before its end
// time: a rejected step, a degenerated body), 2 bad input (message + usage), 130
// interrupted.
//
// Examples:
//   fsi-movie assets/scenarios/ball_drop_demo.json out/demo
//   fsi-movie assets/scenarios/ball_drop.json out/drop --field p --end-time 1 --no-vtu
//   fsi-movie assets/scenarios/ball_drop.json out/k1e-3 --set /numerics/time_step_s=1e-3
//   fsi-movie assets/scenarios/contact/d0_1e-3_g800.json out/gap --zoom -0.3,-1,0.3,-0.9 --mesh
//   fsi-movie assets/scenarios/ball_drop.json out/film --zoom -0.4,-1,0.4,-0.995 --stretch --field p
//   fsi-movie assets/scenarios/ball_drop.json out/talk --second-field p --film-inset
//   fsi-movie assets/scenarios/ball_drop.json out/late --resume out/drop/checkpoints/step_002300.ckpt
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fsi/error.hpp>
#include <string>
#include <vector>

#include "frame_options.hpp"
#include "heap_tuning.hpp"
#include "interrupt_flag.hpp"
#include "movie_run.hpp"
#include "progress_meter.hpp"
#include "scenario_overrides.hpp"

namespace {

constexpr int kExitFailed = 1, kExitBadInput = 2;
constexpr const char* kUsage =
    "usage: fsi-movie SCENARIO.json OUTDIR [--set KEY=VALUE ...] [--frame-every N]\n"
    "                 [--field vx|vy|vmag|p|umag] [--no-video] [--no-png] [--no-vtu]\n"
    "                 [--size WxH] [--fps N] [--zoom x0,y0,x1,y1 [--stretch]] [--mesh]\n"
    "                 [--end-time T] [--quiet] [--checkpoint-every N]\n"
    "                 [--resume CHECKPOINT | --continue]\n"
    "                 [--second-field vx|vy|vmag|p|umag] [--film-inset]\n"
    "  e.g. fsi-movie assets/scenarios/ball_drop_demo.json out/demo --set /solid/mu_pa=4e5\n";

int usage(const std::string& why) {
  std::fprintf(stderr, "fsi-movie: %s\n%s", why.c_str(), kUsage);
  return kExitBadInput;
}

struct Arguments {
  std::string scenario;
  fsi::app::MovieOptions movie;
  std::vector<fsi::app::Override> overrides;
};

// Parses the command line; throws fsi::InputError("command line", option, why).
Arguments parse_arguments(int argc, char** argv) {
  using fsi::app::Override;
  Arguments a;
  std::vector<std::string> positional;
  for (int i = 1; i < argc; ++i) {
    const std::string opt = argv[i];
    auto value = [&] { return fsi::app::option_value(i, argc, argv); };
    if (opt == "--set") {
      a.overrides.push_back(fsi::app::parse_override(value()));
    } else if (opt == "--frame-every") {
      a.overrides.push_back(
          {"/output/frame_every", fsi::app::parse_int(value(), 1, 1000000, "command line", opt)});
    } else if (opt == "--field") {
      const std::string f = value();
      fsi::app::parse_field(f, "command line", opt);
      a.overrides.push_back({"/output/field", f});
    } else if (opt == "--size") {
      int w = 0, h = 0;
      fsi::app::parse_size(value(), "command line", opt, w, h);
      a.overrides.push_back({"/output/width_px", w});
      a.overrides.push_back({"/output/height_px", h});
    } else if (opt == "--fps") {
      a.overrides.push_back(
          {"/output/fps", fsi::app::parse_int(value(), 1, 240, "command line", opt)});
    } else if (opt == "--end-time") {
      a.overrides.push_back(
          {"/numerics/end_time_s", fsi::app::parse_number(value(), "command line", opt)});
    } else if (opt == "--zoom") {
      a.movie.zoom = fsi::app::parse_zoom(value(), "command line", opt);
    } else if (opt == "--second-field") {
      a.movie.second_field = fsi::app::parse_field(value(), "command line", opt);
    } else if (opt == "--film-inset") {
      a.movie.film_inset = true;
    } else if (opt == "--stretch") {
      a.movie.stretch = true;
    } else if (opt == "--mesh") {
      a.overrides.push_back({"/output/mesh_overlay", true});
    } else if (opt == "--no-video") {
      a.movie.video = false;
    } else if (opt == "--no-png") {
      a.movie.png = false;
    } else if (opt == "--no-vtu") {
      a.movie.vtu = false;
    } else if (opt == "--checkpoint-every") {
      a.movie.checkpoint_every = fsi::app::parse_int(value(), 1, 100000000, "command line", opt);
    } else if (opt == "--resume") {
      a.movie.resume_from = value();
    } else if (opt == "--continue") {
      a.movie.continue_run = true;
    } else if (opt == "--quiet") {
      a.movie.quiet = true;
    } else if (opt.size() > 1 && opt[0] == '-') {
      throw fsi::InputError("command line", opt, "unknown option");
    } else {
      positional.push_back(opt);
    }
  }
  if (positional.size() != 2) {
    throw fsi::InputError(
        "command line", "",
        "need SCENARIO.json and OUTDIR, got " + std::to_string(positional.size()) + " argument(s)");
  }
  if (a.movie.continue_run && !a.movie.resume_from.empty()) {
    throw fsi::InputError("command line", "--continue",
                          "continues from OUTDIR's latest checkpoint: do not give --resume too");
  }
  a.scenario = positional[0];
  a.movie.out_dir = positional[1];
  return a;
}

}  // namespace

int main(int argc, char** argv) {
  fsi::app::keep_large_blocks_in_heap();  // see heap_tuning.hpp: a factorization per step
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "-h" || std::string(argv[i]) == "--help") {
      std::fputs(kUsage, stdout);
      return 0;
    }
  }
  Arguments args;
  fsi::Scenario scenario;
  try {
    args = parse_arguments(argc, argv);
    scenario = fsi::app::load_scenario_with_overrides(args.scenario, args.overrides);
  } catch (const fsi::InputError& e) {
    return usage(e.what());
  }
  fsi::app::install_interrupt_handlers();
  try {
    const fsi::app::MovieResult r = fsi::app::run_movie(scenario, args.movie);
    if (!args.movie.quiet || r.unconverged_steps > 0) {
      std::fprintf(stderr, "fsi-movie: %s%ld steps in %s, %ld unconverged; outputs in %s\n",
                   r.interrupted ? "interrupted after " : "", r.steps,
                   fsi::app::ProgressMeter::duration_text(r.wall_seconds).c_str(),
                   r.unconverged_steps, args.movie.out_dir.c_str());
    }
    if (r.interrupted) return fsi::app::kExitInterrupted;
    if (!r.stop_reason.empty()) {
      std::fprintf(stderr, "fsi-movie: stopped before the end time: %s\n", r.stop_reason.c_str());
      return kExitFailed;
    }
    return 0;
  } catch (const fsi::InputError& e) {
    std::fprintf(stderr, "fsi-movie: %s\n", e.what());
    return kExitBadInput;
  } catch (const std::filesystem::filesystem_error& e) {
    std::fprintf(stderr, "fsi-movie: cannot write the outputs: %s\n", e.what());
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fsi-movie: %s\n", e.what());
    return kExitFailed;
  }
}
