// fsi-render-examples: writes example pictures of the renderer, made from the synthetic
// falling-ball field (no engine run needed), to look at or put on a slide.
//
//   fsi-render-examples OUT_DIR [--size WIDTHxHEIGHT] [--no-video]
//
// Writes OUT_DIR/{vy,vmag_mesh,p,umag_zoom,contact_gap_stretched,vy_p_film_inset}.png,
// plot.png, plot_log.png and (when built with video) falling_ball.mp4.
//
// Examples:
//   fsi-render-examples out/render-examples
//   FSI_GL_BACKEND=egl fsi-render-examples out/render-examples-egl --size 1920x1080
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fsi/plot.hpp>
#include <fsi/png.hpp>
#include <fsi/renderer.hpp>
#include <fsi/sample_field.hpp>
#include <string>
#ifdef FSI_RENDER_HAS_VIDEO
#include <fsi/video.hpp>
#endif

namespace {

using namespace fsi::render;

int usage(const char* why) {
  std::fprintf(stderr,
               "fsi-render-examples: %s\nusage: fsi-render-examples OUT_DIR "
               "[--size WIDTHxHEIGHT] [--no-video]\n",
               why);
  return 2;
}

void write(const std::filesystem::path& file, const Image& im) {
  write_png(file, im);
  std::printf("wrote %s (%dx%d)\n", file.c_str(), im.width, im.height);
}

// Functionals of the synthetic drop, shaped like the real ones (not physics).
PlotSpec functionals_plot(int width, int height) {
  PlotSpec p;
  p.title = "Ball dropping onto the ground";
  p.x_label = "t [s]";
  p.y_label = "[m]";
  p.width = width;
  p.height = height;
  PlotSeries gap{"distance to ground", {}, {}}, w{"ball width", {}, {}}, h{"ball height", {}, {}};
  for (int i = 0; i <= 400; ++i) {
    const double t = 0.005 * i;
    const double d = std::max(0.002, 0.4 - 0.25 * t * t) +
                     0.01 * std::exp(-8 * (t - 1.3) * (t - 1.3)) * (t > 1.26);
    const double squash = 0.03 * std::exp(-20 * (t - 1.3) * (t - 1.3));
    gap.x.push_back(t), gap.y.push_back(d);
    w.x.push_back(t), w.y.push_back(0.6 + squash);
    h.x.push_back(t), h.y.push_back(0.6 - squash);
  }
  p.series = {gap, w, h};
  return p;
}

}  // namespace

int main(int argc, char** argv) {
  std::filesystem::path out;
  int width = 1280, height = 720;
  bool video = true;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--no-video") {
      video = false;
    } else if (a == "--size" && i + 1 < argc) {
      if (std::sscanf(argv[++i], "%dx%d", &width, &height) != 2 || width < 160 || height < 120) {
        return usage("--size wants WIDTHxHEIGHT, at least 160x120");
      }
    } else if (!a.empty() && a[0] != '-' && out.empty()) {
      out = a;
    } else {
      return usage(("unexpected argument " + a).c_str());
    }
  }
  if (out.empty()) return usage("need OUT_DIR");
  try {
    Renderer r;
    const fsi::FieldView view = sample_field_view({.nx = 49, .ny = 37, .graded = true});
    FrameSpec s;
    s.width = width;
    s.height = height;
    s.title = "Falling ball (synthetic field)";

    s.quantity = Quantity::vy;
    write(out / "vy.png", r.render(view, s));
    s.quantity = Quantity::vmag;
    s.show_mesh = true;
    write(out / "vmag_mesh.png", r.render(view, s));
    s.show_mesh = false;
    s.quantity = Quantity::p;
    write(out / "p.png", r.render(view, s));
    s.quantity = Quantity::umag;
    s.window = ViewWindow{-0.35, -0.75, 0.55, -0.05};
    s.title = "Zoom on the ball";
    write(out / "umag_zoom.png", r.render(view, s));
    s.quantity = Quantity::vy;
    s.window = ViewWindow{-0.4, -1.0, 0.6, -0.62};
    s.keep_aspect = false;
    s.show_mesh = true;
    s.title = "Gap under the ball (stretched)";
    write(out / "contact_gap_stretched.png", r.render(view, s));

    // Velocity and pressure side by side, the ball 4 cm above the floor: the film under
    // it magnified in each panel's inset.
    const fsi::FieldView near_floor =
        sample_field_view({.nx = 49, .ny = 37, .graded = true, .ball_y = -0.66});
    FrameSpec two;
    two.width = width;
    two.height = height;
    two.title = "Near contact";
    two.quantity = Quantity::vy;
    two.second_quantity = Quantity::p;
    two.inset = film_window(near_floor);
    write(out / "vy_p_film_inset.png", r.render(near_floor, two));

    PlotSpec p = functionals_plot(width * 3 / 4, height * 3 / 4);
    write(out / "plot.png", r.plot(p));
    p.log_y = true;
    p.title = "The same on a log axis";
    write(out / "plot_log.png", r.plot(p));

#ifdef FSI_RENDER_HAS_VIDEO
    if (video) {
      FrameSpec m;
      m.width = width;
      m.height = height;
      m.quantity = Quantity::vy;
      m.range = ColorRange{-0.2, 0.2};  // fixed for the whole movie: no flicker
      m.title = "Falling ball (synthetic field)";
      VideoWriter writer(out / "falling_ball.mp4", width, height);
      for (int k = 0; k < 50; ++k) {
        const double t = k / 25.0;
        writer.write(r.render(
            sample_field_view(
                {.nx = 49, .ny = 37, .graded = true, .time_s = t, .ball_y = 0.0 - 0.3 * t}),
            m));
      }
      writer.close();
      std::printf("wrote %s (%ld frames, %s)\n", (out / "falling_ball.mp4").c_str(),
                  writer.frames_written(), writer.encoder_name().c_str());
    }
#else
    (void)video;
#endif
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fsi-render-examples: %s\n", e.what());
    return 1;
  }
  return 0;
}
