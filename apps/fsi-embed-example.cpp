// fsi-embed-example: how a program of your own uses fsi. Builds a scenario in code,
// steps it, prints the functionals, renders a frame and writes ParaView files.
// Read it top to bottom; it is documentation first.
//
//   fsi-embed-example [OUT_DIR]      (default: out/embed-example)
//
// Examples:
//   fsi-embed-example
//   fsi-embed-example /tmp/embed && xdg-open /tmp/embed/frame.png
//
// In your own CMake project (after `cmake --install build --prefix <prefix>`):
//   find_package(fsi REQUIRED)
//   target_link_libraries(app PRIVATE fsi::engine fsi::render)
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fsi/engine.hpp>    // fsi::Engine, StepReport, checkpoints
#include <fsi/output.hpp>    // VTU/PVD and functionals CSV writers
#include <fsi/png.hpp>       // fsi::render::write_png
#include <fsi/renderer.hpp>  // fsi::render::Renderer, FrameSpec
#include <fsi/scenario.hpp>  // fsi::Scenario, example1_scenario(), validate()

int main(int argc, char** argv) {
  const std::filesystem::path out = argc > 1 ? argv[1] : "out/embed-example";
  try {
    // 1. A scenario: start from the chapter's Example 1 and change what you need.
    //    Every field has its unit in its name; see engine/include/fsi/scenario.hpp.
    fsi::Scenario s = fsi::example1_scenario();
    s.name = "embedded_throw";
    s.body.initial_velocity_mps = {0.2, -0.3};  // thrown to the right and down
    s.numerics.time_step_s = 0.01;
    // A coarse mesh (8 + 8 x 16 patches, ~1100 nodes): fine for a quick look.
    fsi::BlockSpec block;
    block.x = {fsi::AxisPiece{0.0, -1.0, 8, 0.05, 0.2}, fsi::AxisPiece{0.0, 1.0, 8, 0.05, 0.2}};
    block.y = {fsi::AxisPiece{-1.0, 0.5, 16, 0.00625, 0.3}};
    s.mesh.blocks = {block};
    fsi::validate(s);  // throws fsi::InputError naming the key and the allowed range

    // 2. The engine owns the discretization and the state; step() advances one k.
    fsi::Engine engine(s);
    std::filesystem::create_directories(out);
    fsi::io::FunctionalsCsv csv(out / "functionals.csv", /*with_newton_columns=*/true);
    for (int i = 0; i < 20; ++i) {
      const fsi::StepReport report = engine.step();
      csv.append(engine.state(), report);
      // Numerical trouble is reported, not thrown: look at it.
      if (!report.converged) std::fprintf(stderr, "step %d: %s\n", i + 1, report.message.c_str());
    }

    // 3. The chapter's quantities of interest travel with the state.
    const fsi::Functionals& f = engine.state().functionals;
    std::printf("t = %.3f s after %ld steps\n", engine.state().time_s, engine.state().step);
    std::printf("  min distance to the ground %.4f m, centroid (%.4f, %.4f) m\n", f.min_distance_m,
                f.centroid_x_m, f.centroid_y_m);
    std::printf("  mean velocity (%.4f, %.4f) m/s, mass error %.2e\n", f.mean_vx_mps, f.mean_vy_mps,
                f.mass_error);

    // 4. Pictures: the renderer only ever sees a FieldView (a copy of mesh and fields).
    const fsi::FieldView view = engine.view();
    fsi::render::Renderer renderer;  // offscreen OSMesa; reuse it for many frames
    fsi::render::FrameSpec spec;
    spec.width = 800;
    spec.height = 450;
    spec.quantity = fsi::render::Quantity::vmag;
    fsi::render::write_png(out / "frame.png", renderer.render(view, spec));

    // 5. ParaView: one .vtu + .vtp per frame, listed in a .pvd time series.
    fsi::io::PvdSeries series(out / "frames.pvd");
    fsi::io::write_vtk_frame(out, "frame", view, series);

    // 6. Checkpoints: save, continue elsewhere bit-identically with load_checkpoint.
    fsi::save_checkpoint(engine, out / "state.ckpt");
    std::printf("wrote %s/{frame.png,functionals.csv,frames.pvd,state.ckpt}\n", out.c_str());
    return 0;
  } catch (const std::exception& e) {  // fsi::InputError for bad input, else I/O trouble
    std::fprintf(stderr, "fsi-embed-example: %s\n", e.what());
    return 1;
  }
}
