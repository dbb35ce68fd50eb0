// fsi-sketch: a picture of a scenario's geometry -- the mesh (patch outlines and
// sub-elements), the walls and the ball at t = 0 -- to check a new geometry by eye (walls
// where they should be, fine cells where the ball lands). With --contours it draws the
// ball's interface at t = 0 and at the times of a run's checkpoints on top of each other,
// the chapter's Fig. 12.11 ("contour plots of the interface at several times").
//
//   fsi-sketch SCENARIO.json OUT.png [--size WxH] [--window X0,Y0,X1,Y1]
//              [--set KEY=VALUE ...] [--contours CHECKPOINT|DIR ...] [--every N] [--no-mesh]
//
// --contours takes checkpoint files or folders of them (every step_*.ckpt in it, in step
// order); --every N keeps every N-th of them (the last one always). The checkpoints must
// belong to the scenario: pass the run's own OUTDIR/scenario.json (fsi-movie writes it with
// its --set changes) or the same --set changes. A checkpoint written before
// tools/rewind-run changed the run's numerics belongs to OUTDIR/rewound-*/scenario.json
// (the run's scenario as it was then), which is tried next. Prints the node and patch
// counts and the contours' times. Exit 0 on success, 2 on bad input.
//
// Examples:
//   fsi-sketch assets/scenarios/stairs/stairs_rho1000.json assets/scenarios/stairs/stairs_sketch.png
//   fsi-sketch out/study-stairs/rho150/scenario.json out/rho150_contours.png
//              --contours out/study-stairs/rho150/checkpoints --every 2 --no-mesh
#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fsi/engine.hpp>
#include <fsi/error.hpp>
#include <fsi/png.hpp>
#include <fsi/renderer.hpp>
#include <string>
#include <utility>
#include <vector>

#include "frame_options.hpp"
#include "scenario_overrides.hpp"

namespace {

namespace fs = std::filesystem;

constexpr const char* kUsage =
    "usage: fsi-sketch SCENARIO.json OUT.png [--size WxH] [--window X0,Y0,X1,Y1]\n"
    "                  [--set KEY=VALUE ...] [--contours CHECKPOINT|DIR ...] [--every N] [--no-mesh]\n";

struct Arguments {
  std::string scenario, out;
  std::vector<fsi::app::Override> overrides;
  std::vector<fs::path> contours;  ///< checkpoint files, in the order given
  int every = 1;
  fsi::render::FrameSpec spec;
};

// The checkpoint files of one --contours argument: the file, or a folder's step_*.ckpt
// in step order (the names carry the step zero-padded, so name order is step order).
std::vector<fs::path> checkpoint_files(const fs::path& where) {
  if (!fs::is_directory(where)) {
    if (!fs::is_regular_file(where)) throw fsi::InputError(where.string(), "--contours", "no such file or folder");
    return {where};
  }
  std::vector<fs::path> files;
  for (const fs::directory_entry& e : fs::directory_iterator(where)) {
    const std::string name = e.path().filename().string();
    if (e.is_regular_file() && name.rfind("step_", 0) == 0 && e.path().extension() == ".ckpt")
      files.push_back(e.path());
  }
  if (files.empty()) throw fsi::InputError(where.string(), "--contours", "no step_*.ckpt in this folder");
  std::sort(files.begin(), files.end());
  return files;
}

Arguments parse_arguments(int argc, char** argv) {
  Arguments a;
  a.spec.width = 1600;
  a.spec.height = 1000;
  a.spec.quantity = fsi::render::Quantity::vx;
  a.spec.range = fsi::render::ColorRange{-1.0, 1.0};  // fields are drawn as 0 (see main)
  a.spec.show_mesh = true;
  a.spec.show_colorbar = false;
  a.spec.show_time = false;
  std::vector<std::string> positional;
  for (int i = 1; i < argc; ++i) {
    const std::string opt = argv[i];
    auto value = [&] { return fsi::app::option_value(i, argc, argv); };
    if (opt == "--size") {
      fsi::app::parse_size(value(), "command line", opt, a.spec.width, a.spec.height);
    } else if (opt == "--window") {
      a.spec.window = fsi::app::parse_zoom(value(), "command line", opt);
    } else if (opt == "--set") {
      a.overrides.push_back(fsi::app::parse_override(value()));
    } else if (opt == "--contours") {
      for (const fs::path& f : checkpoint_files(value())) a.contours.push_back(f);
    } else if (opt == "--every") {
      a.every = fsi::app::parse_int(value(), 1, 1000000, "command line", opt);
    } else if (opt == "--no-mesh") {
      a.spec.show_mesh = false;
    } else if (opt.size() > 1 && opt[0] == '-') {
      throw fsi::InputError("command line", opt, "unknown option");
    } else {
      positional.push_back(opt);
    }
  }
  if (positional.size() != 2) {
    throw fsi::InputError("command line", "",
                          "need SCENARIO.json and OUT.png, got " + std::to_string(positional.size()) +
                              " argument(s)");
  }
  a.scenario = positional[0];
  a.out = positional[1];
  return a;
}

/// The scenarios a run had before tools/rewind-run changed its numerics
/// (RUN/rewound-*/scenario.json, oldest first), RUN being the folder of `checkpoints/`.
std::vector<fs::path> earlier_scenarios(const fs::path& checkpoint) {
  std::vector<fs::path> found;
  const fs::path run = checkpoint.parent_path().parent_path();
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(run.empty() ? "." : run, ec)) {
    const fs::path candidate = e.path() / "scenario.json";
    if (e.path().filename().string().rfind("rewound-", 0) == 0 && fs::exists(candidate))
      found.push_back(candidate);
  }
  std::sort(found.begin(), found.end());
  return found;
}

/// Loads `file` into `engine` (the scenario given) or, when the checkpoint was written
/// with the numerics the run had before a rewind, into an engine of that scenario (kept
/// in `earlier`, made once). Returns the engine that holds it.
const fsi::Engine& load_contour(fsi::Engine& engine, const fs::path& file,
                                std::vector<std::pair<fs::path, fsi::Engine>>& earlier) {
  try {
    fsi::load_checkpoint(engine, file);
    return engine;
  } catch (const fsi::InputError& e) {
    if (e.key() != "/fingerprint") throw;  // not a question of the scenario
    for (const fs::path& scenario : earlier_scenarios(file)) {
      auto it = std::find_if(earlier.begin(), earlier.end(), [&](const auto& p) { return p.first == scenario; });
      if (it == earlier.end()) it = earlier.emplace(earlier.end(), scenario, fsi::Engine(fsi::load_scenario(scenario)));
      try {
        fsi::load_checkpoint(it->second, file);
        return it->second;
      } catch (const fsi::InputError&) {
      }
    }
    throw;  // the first error: the checkpoint belongs to none of them
  }
}

// Every `every`-th file and the last one.
std::vector<fs::path> thinned(const std::vector<fs::path>& files, int every) {
  std::vector<fs::path> kept;
  for (std::size_t i = 0; i < files.size(); ++i)
    if (i % std::size_t(every) == 0 || i + 1 == files.size()) kept.push_back(files[i]);
  return kept;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    Arguments a = parse_arguments(argc, argv);
    fsi::Engine engine(fsi::app::load_scenario_with_overrides(a.scenario, a.overrides));
    fsi::FieldView view = engine.view();
    std::string times;  // "0, 0.5, 1, ..." for the printout
    double last_time_s = 0;
    std::size_t contours = 0;
    if (!a.contours.empty()) {
      // The t = 0 picture with every checkpoint's interface added to the initial one.
      times = "0";
      std::vector<std::pair<fs::path, fsi::Engine>> earlier;  // scenarios before rewinds
      for (const fs::path& f : thinned(a.contours, a.every)) {
        const fsi::FieldView at = load_contour(engine, f, earlier).view();
        view.interface.insert(view.interface.end(), at.interface.begin(), at.interface.end());
        char t[32];
        std::snprintf(t, sizeof t, ", %.4g", at.time_s);
        times += t;
        last_time_s = at.time_s;
        ++contours;
      }
    }
    // A plain background: the geometry is the point, not the (last) state's fields.
    std::fill(view.vx.begin(), view.vx.end(), 0.0);
    a.spec.title = engine.scenario().name + ": " + std::to_string(view.nodes.size()) + " nodes";
    if (contours > 0) {
      char t[96];
      std::snprintf(t, sizeof t, ": the ball at %zu times, t = 0 to %.4g s", contours + 1, last_time_s);
      a.spec.title = engine.scenario().name + t;
    }
    fsi::render::Renderer renderer;
    fsi::render::write_png(a.out, renderer.render(view, a.spec));
    std::printf("%s: %zu nodes, %zu triangles, %zu walls%s%s -> %s\n", engine.scenario().name.c_str(),
                view.nodes.size(), view.triangles.size(), view.walls.size(),
                times.empty() ? "" : ", contours at t = ", times.c_str(), a.out.c_str());
  } catch (const std::exception& e) {
    const bool other_scenario = std::string(e.what()).find("fingerprint") != std::string::npos;
    std::fprintf(stderr, "fsi-sketch: %s\n%s%s", e.what(),
                 other_scenario ? "(pass the run's OUTDIR/scenario.json, or its --set changes)\n" : "",
                 kUsage);
    return 2;
  }
  return 0;
}
