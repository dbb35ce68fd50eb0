// Golden pictures of field frames (320x240, small enough to check in), and properties
// of the colouring that must hold whatever the goldens say.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <filesystem>
#include <fsi/colormap.hpp>
#include <fsi/engine.hpp>
#include <fsi/renderer.hpp>
#include <fsi/sample_field.hpp>

#include "image/golden.hpp"

namespace fsi::render {
namespace {

FrameSpec small_frame(Quantity q) {
  FrameSpec s;
  s.width = 320;
  s.height = 240;
  s.quantity = q;
  return s;
}

class FieldFrame : public ::testing::Test {
 protected:
  Renderer renderer{GlBackend::osmesa};
  FieldView view = sample_field_view();
};

TEST_F(FieldFrame, SignedVelocityWithContourGolden) {
  testing::expect_matches_golden("field_vy_contour",
                                 renderer.render(view, small_frame(Quantity::vy)));
}

TEST_F(FieldFrame, MagnitudeViridisWithMeshGolden) {
  FrameSpec s = small_frame(Quantity::vmag);
  s.show_mesh = true;
  testing::expect_matches_golden("field_vmag_mesh", renderer.render(view, s));
}

TEST_F(FieldFrame, PressureFixedRangeTitleGolden) {
  FrameSpec s = small_frame(Quantity::p);
  s.range = ColorRange{-500, 500};
  s.title = "pressure";
  testing::expect_matches_golden("field_p_fixed_range", renderer.render(view, s));
}

TEST_F(FieldFrame, ZoomedStretchedDisplacementGolden) {
  FrameSpec s = small_frame(Quantity::umag);
  s.window = ViewWindow{-0.3, -0.75, 0.5, -0.6};  // the gap under the ball
  s.keep_aspect = false;
  s.show_mesh = true;
  testing::expect_matches_golden("field_umag_zoom_stretched", renderer.render(view, s));
}

TEST_F(FieldFrame, ColorBarAloneGolden) {
  // No axes, no time stamp: the colour bar (fixed range, its ticks and label) and the
  // field fill the picture.
  FrameSpec s = small_frame(Quantity::vx);
  s.range = ColorRange{-0.25, 0.25};
  s.show_axes = false;
  s.show_time = false;
  testing::expect_matches_golden("colorbar_cool_warm", renderer.render(view, s));
}

TEST_F(FieldFrame, TwoPanelsWithFilmInsetGolden) {
  // Velocity and pressure side by side, each with the film under the ball (4.3 cm gap,
  // under half the radius) magnified in its upper right corner.
  SampleFieldOptions o;
  o.ball_y = -0.657;
  const FieldView near_floor = sample_field_view(o);
  FrameSpec s = small_frame(Quantity::vy);
  s.width = 480;
  s.second_quantity = Quantity::p;
  s.inset = film_window(near_floor);
  ASSERT_TRUE(s.inset);
  testing::expect_matches_golden("field_two_panels_inset", renderer.render(near_floor, s));
}

/// The sample view with two more bodies' contours (circles of radius 0.15 m), each
/// interface segment labelled with its body as the engine labels them.
FieldView three_bodies(const FieldView& one) {
  FieldView v = one;
  v.interface_body.assign(v.interface.size(), 0);
  const double centres[2][2] = {{-0.6, 0.1}, {0.65, -0.1}};
  for (int b = 0; b < 2; ++b)
    for (int k = 0; k < 64; ++k) {
      const double a0 = 2 * std::numbers::pi * k / 64, a1 = 2 * std::numbers::pi * (k + 1) / 64;
      v.interface.push_back({{centres[b][0] + 0.15 * std::cos(a0), centres[b][1] + 0.15 * std::sin(a0)},
                             {centres[b][0] + 0.15 * std::cos(a1), centres[b][1] + 0.15 * std::sin(a1)}});
      v.interface_body.push_back(b + 1);
    }
  return v;
}

TEST_F(FieldFrame, EachBodyInItsOwnColourGolden) {
  const FieldView v = three_bodies(view);
  FrameSpec s = small_frame(Quantity::vmag);
  const Image image = renderer.render(v, s);
  testing::expect_matches_golden("field_three_bodies", image);
  // body2's contour is drawn in magenta, body3's in green; all black when asked.
  const auto has_pixel = [](const Image& im, auto near) {
    for (int y = 0; y < im.height; ++y)
      for (int x = 0; x < im.width; ++x) {
        const std::uint8_t* p = &im.rgba[4 * (static_cast<std::size_t>(y) * im.width + x)];
        if (near(p[0], p[1], p[2])) return true;
      }
    return false;
  };
  const auto magenta = [](int r, int g, int b) { return r > 170 && g < 40 && b > 170; };
  const auto green = [](int r, int g, int b) { return r < 40 && g > 110 && g < 170 && b < 40; };
  EXPECT_TRUE(has_pixel(image, magenta));
  EXPECT_TRUE(has_pixel(image, green));
  s.colour_bodies = false;
  const Image plain = renderer.render(v, s);
  EXPECT_FALSE(has_pixel(plain, magenta));
}

TEST_F(FieldFrame, EngineSceneOfTwoBodiesGolden) {
  // The engine's own view of assets/scenarios/bodies/two_balls_collide.json at t = 0: two
  // balls flying at each other in their potential flows, body2's contour in magenta.
  const fsi::Engine engine(
      fsi::load_scenario(std::filesystem::path(FSI_SOURCE_DIR) / "assets/scenarios/bodies/two_balls_collide.json"));
  FrameSpec s = small_frame(Quantity::vx);
  s.range = ColorRange{-0.4, 0.4};
  testing::expect_matches_golden("engine_two_bodies", renderer.render(engine.view(), s));
}

TEST_F(FieldFrame, FilmWindowSpansTheGapUnderTheBody) {
  SampleFieldOptions o;  // radius 0.3 m, floor at y = -1
  o.ball_y = -0.69;      // lowest point -0.99: a 1 cm film
  const FieldView v = sample_field_view(o);
  const auto w = film_window(v);
  ASSERT_TRUE(w);
  double lowest = 1e9;
  for (const auto& sg : v.interface) lowest = std::min({lowest, sg.a.y, sg.b.y});
  const double gap = lowest + 1.0;
  EXPECT_LT(w->y0, -1.0);                         // the floor inside
  EXPECT_NEAR(w->y1, lowest + 0.6 * gap, 1e-12);  // and a little of the ball
  EXPECT_LT(w->x0, o.ball_x - 0.2);               // the lower part of the ball's width
  EXPECT_GT(w->x1, o.ball_x + 0.2);
  o.ball_y = -0.3;  // 40 cm up: no film to show
  EXPECT_FALSE(film_window(sample_field_view(o)));
  FieldView none = v;
  none.interface.clear();
  EXPECT_FALSE(film_window(none));
}

TEST_F(FieldFrame, ReusedImageMatchesAFreshOne) {
  // A movie renders into one Image frame after frame; a size change in between and
  // back must leave nothing of the other size behind.
  FrameSpec s = small_frame(Quantity::vmag);
  Image reused;
  renderer.render(view, s, reused);
  s.width = 200;
  renderer.render(view, s, reused);
  s.width = 320;
  renderer.render(view, s, reused);
  EXPECT_TRUE(compare_images(renderer.render(view, s), reused, 0, 0.0).same);
}

// The scalar is interpolated before the colour lookup: along a linear field every pixel
// has the colour of its own value. Interpolating colours instead would fail this (the
// viridis table is not linear in RGB between the two end nodes).
TEST_F(FieldFrame, ColoursAreMappedPerPixel) {
  FieldView v;
  v.nodes = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  v.triangles = {{0, 1, 2}, {0, 2, 3}};
  v.vx = {0, 1, 1, 0};  // vx = x
  v.vy = {0, 0, 0, 0};
  v.domain_min = {0, 0};
  v.domain_max = {1, 1};
  FrameSpec s;
  s.width = 300;
  s.height = 200;
  s.quantity = Quantity::vx;
  s.range = ColorRange{0, 1};
  s.window = ViewWindow{0, 0, 1, 1};
  s.keep_aspect = false;
  s.show_axes = s.show_colorbar = s.show_time = s.show_interface = s.show_walls = false;
  s.supersample = 1;
  const Image im = renderer.render(v, s);
  // Find the plot area: the run of non-white, non-frame pixels along the middle row.
  const int y = im.height / 2;
  int x0 = -1, x1 = -1;
  for (int x = 0; x < im.width; ++x) {
    const std::uint8_t* p = &im.rgba[im.offset(x, y)];
    const bool ink =
        !(p[0] > 250 && p[1] > 250 && p[2] > 250) && !(p[0] < 40 && p[1] < 40 && p[2] < 40);
    if (ink && x0 < 0) x0 = x;
    if (ink) x1 = x;
  }
  ASSERT_GT(x1 - x0, 100);
  // vx = x is cool-warm from blue (-1 side, not reached) to red; sample inner pixels.
  int worst = 0;
  for (int x = x0 + 3; x <= x1 - 3; x += 5) {
    const double t = (x + 0.5 - x0) / double(x1 - x0 + 1);  // 0..1 across the area
    const Rgb8 want = colormap_color(Colormap::cool_warm, t);
    const std::uint8_t* p = &im.rgba[im.offset(x, y)];
    worst = std::max(
        {worst, std::abs(p[0] - want.r), std::abs(p[1] - want.g), std::abs(p[2] - want.b)});
  }
  EXPECT_LE(worst, 6) << "pixel colours do not follow the colour map of the interpolated value";
}

TEST_F(FieldFrame, FixedRangeGivesSameColoursForSameValues) {
  // A movie fixes the range: the same value must keep its colour whatever the frame's
  // own extremes are.
  FrameSpec s = small_frame(Quantity::vy);
  s.range = ColorRange{-1, 1};
  FieldView doubled = view;
  doubled.vx[0] = 50;  // an outlier far away changes the auto range, not a fixed one
  const Image a = renderer.render(view, s), b = renderer.render(doubled, s);
  EXPECT_TRUE(compare_images(a, b, 0, 0.0).same);
}

TEST_F(FieldFrame, RejectsInconsistentViews) {
  FieldView bad = view;
  bad.vx.pop_back();
  EXPECT_THROW(renderer.render(bad, small_frame(Quantity::vx)), std::invalid_argument);
  bad = view;
  bad.triangles.push_back({0, 1, int(view.nodes.size())});
  EXPECT_THROW(renderer.render(bad, small_frame(Quantity::vx)), std::invalid_argument);
  FrameSpec s = small_frame(Quantity::vx);
  s.window = ViewWindow{1, 0, 0, 1};
  EXPECT_THROW(renderer.render(view, s), std::invalid_argument);
}

TEST_F(FieldFrame, OutputHasRequestedSizeAndIsOpaque) {
  FrameSpec s = small_frame(Quantity::vmag);
  s.width = 333;
  s.height = 201;
  const Image im = renderer.render(view, s);
  ASSERT_EQ(im.width, 333);
  ASSERT_EQ(im.height, 201);
  // Top-left corner is background white: the picture is not upside down or black.
  EXPECT_EQ(im.rgba[0], 255);
  // Every pixel opaque, the antialiased edges of lines and text too (blending must not
  // lower the alpha of the paper under them).
  int translucent = 0;
  for (std::size_t i = 3; i < im.rgba.size(); i += 4) translucent += im.rgba[i] != 255;
  EXPECT_EQ(translucent, 0);
}

TEST_F(FieldFrame, ALongTitleStaysInsideThePicture) {
  // Wider than the picture at the title's size: drawn smaller, so the last few columns
  // of the title band stay background white instead of holding cut-off letters.
  FrameSpec s = small_frame(Quantity::vmag);
  s.show_colorbar = false;
  s.title = "stairs_rho1000: the ball at 12 times, t = 0 to 11.5 s";
  const Image im = renderer.render(view, s);
  int inked = 0;
  for (int y = 0; y < im.height / 6; ++y) {
    for (int x = im.width - 4; x < im.width; ++x) {
      if (im.rgba[4 * (std::size_t(y) * im.width + x)] < 200) ++inked;
    }
  }
  EXPECT_EQ(inked, 0);
}

}  // namespace
}  // namespace fsi::render
