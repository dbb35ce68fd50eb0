// fsi-sketch: a picture of a scenario's geometry before it runs -- the mesh (patch
// outlines and sub-elements), the walls and the ball at t = 0 -- to check a new geometry
// by eye (walls where they should be, fine cells where the ball lands).
//
//   fsi-sketch SCENARIO.json OUT.png [--size WIDTHxHEIGHT] [--window X0,Y0,X1,Y1]
//
// Prints the node and patch counts. Exit 0 on success, 2 on bad input.
//
// Example:
//   fsi-sketch assets/scenarios/stairs/stairs_rho1000.json assets/scenarios/stairs/stairs_sketch.png
#include <cstdio>
#include <exception>
#include <fsi/engine.hpp>
#include <fsi/png.hpp>
#include <fsi/renderer.hpp>
#include <string>

namespace {

int usage(const std::string& why) {
  std::fprintf(stderr,
               "fsi-sketch: %s\nusage: fsi-sketch SCENARIO.json OUT.png [--size WIDTHxHEIGHT] "
               "[--window X0,Y0,X1,Y1]\n",
               why.c_str());
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return usage("needs a scenario and an output file");
  fsi::render::FrameSpec spec;
  spec.width = 1600;
  spec.height = 1000;
  spec.quantity = fsi::render::Quantity::vx;
  spec.range = fsi::render::ColorRange{-1.0, 1.0};  // all fields are 0 at t = 0
  spec.show_mesh = true;
  spec.show_colorbar = false;
  spec.show_time = false;
  for (int i = 3; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i + 1 >= argc) return usage("missing value after " + arg);
    const char* value = argv[++i];
    if (arg == "--size") {
      if (std::sscanf(value, "%dx%d", &spec.width, &spec.height) != 2) return usage("bad --size");
    } else if (arg == "--window") {
      fsi::render::ViewWindow w;
      if (std::sscanf(value, "%lf,%lf,%lf,%lf", &w.x0, &w.y0, &w.x1, &w.y1) != 4) return usage("bad --window");
      spec.window = w;
    } else {
      return usage("unknown option " + arg);
    }
  }
  try {
    const fsi::Engine engine(fsi::load_scenario(argv[1]));
    const fsi::FieldView view = engine.view();
    spec.title = engine.scenario().name + ": " + std::to_string(view.nodes.size()) + " nodes";
    fsi::render::Renderer renderer;
    fsi::render::write_png(argv[2], renderer.render(view, spec));
    std::printf("%s: %zu nodes, %zu triangles, %zu walls -> %s\n", engine.scenario().name.c_str(),
                view.nodes.size(), view.triangles.size(), view.walls.size(), argv[2]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fsi-sketch: %s\n", e.what());
    return 2;
  }
  return 0;
}
