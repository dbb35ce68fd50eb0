#pragma once
/// \file renderer.hpp
/// Turns a FieldView into a picture: a scalar field coloured per pixel, the interface as
/// a thick black contour, walls, an optional mesh overlay, axes in metres, a colour bar
/// with unit and a time stamp. Also draws plots (see plot.hpp) with the same machinery.
///
/// One Renderer owns one offscreen GL context (OSMesa by default, EGL with
/// FSI_GL_BACKEND=egl); use one per thread. Reusing a Renderer across the frames of a
/// movie avoids re-creating the context.
#include <fsi/field_view.hpp>
#include <memory>
#include <optional>
#include <string>

#include "fsi/field_quantity.hpp"
#include "fsi/image.hpp"
#include "fsi/render_context.hpp"

namespace fsi::render {

struct PlotSpec;  // plot.hpp

/// A rectangle of the domain [m].
struct ViewWindow {
  double x0 = 0, y0 = 0, x1 = 1, y1 = 1;  ///< [m], x0 < x1, y0 < y1
};

/// What one frame shows. Defaults give a 1280x720 |v| picture of the whole domain.
struct FrameSpec {
  int width = 1280;  ///< [px]
  int height = 720;  ///< [px]
  Quantity quantity = Quantity::vmag;
  /// Fixed colour range (in the quantity's unit); unset = auto_range() of this frame.
  /// Fix it for a movie, or the colours flicker from frame to frame.
  std::optional<ColorRange> range;
  /// Zoom window [m]; unset = the domain's bounding box.
  std::optional<ViewWindow> window;
  /// true: one metre is as long in x as in y (letterboxed); false: stretch the window to
  /// fill the plot area (useful for thin contact gaps, e.g. 1e-3 m high).
  bool keep_aspect = true;
  bool show_mesh = false;      ///< thin grey sub-element edges
  bool show_interface = true;  ///< thick black interface contour
  /// Several bodies: each body's contour in a colour of its own (body1 black, body2
  /// magenta, body3 green, body4 orange, then again); false: all black.
  bool colour_bodies = true;
  bool show_walls = true;      ///< thick dark grey walls
  bool show_colorbar = true;
  bool show_axes = true;  ///< ticks and labels in metres on the frame
  bool show_time = true;  ///< "t = 1.234 s" top left
  int time_decimals = 3;  ///< digits after the point of the time stamp
  std::string title;      ///< top centre; empty = none
  /// Text size factor; 0 = automatic from the picture height (legible at any size).
  double text_scale = 0;
  /// A second quantity in a panel of its own right of the first (e.g. velocity and
  /// pressure side by side), with its own colour bar; unset = one panel.
  std::optional<Quantity> second_quantity;
  /// Fixed colour range of the second panel; unset = auto_range() of this frame.
  std::optional<ColorRange> second_range;
  /// A magnified inset of this window [m] in the upper right corner of each panel,
  /// stretched to the inset's box (x and y scaled apart: a film 1 mm high under a ball
  /// becomes visible), its outline marked in the panel. See film_window().
  std::optional<ViewWindow> inset;
  /// Supersampling factor per direction (1..4). Lines and text are antialiased at 1
  /// already; 2 also smooths the edges of the coloured field (the ball's rim under its
  /// contour line), at about 4x the drawing time (BM_Render: 32 against 8 ms).
  int supersample = 1;
};

/// The film under the body, for FrameSpec::inset: from just below the floor (the
/// domain's bottom) to 0.6 gap above the interface's lowest point, as wide as the body
/// is within 0.6 radius above that point (plus 5 % each side). Its height follows the
/// gap, so the inset magnifies more as the body comes down. Unset when the view has no
/// interface or the gap is wider than half the body's radius (no film to show yet).
std::optional<ViewWindow> film_window(const FieldView& view);

class Renderer {
 public:
  /// Opens a context of the backend chosen by FSI_GL_BACKEND (osmesa default).
  Renderer();
  explicit Renderer(GlBackend backend);
  ~Renderer();
  Renderer(Renderer&&) noexcept;
  Renderer& operator=(Renderer&&) noexcept;

  /// Draws one frame. Throws std::invalid_argument when `view` is inconsistent (field
  /// sizes differ from the node count, indices out of range) or the spec is unusable.
  Image render(const FieldView& view, const FrameSpec& spec);
  /// The same into `into`, whose storage is reused when the size is unchanged (no
  /// allocation per frame in a movie loop).
  void render(const FieldView& view, const FrameSpec& spec, Image& into);

  /// Draws a plot of functionals over time (see plot.hpp).
  Image plot(const PlotSpec& spec);

  GlBackend backend() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fsi::render
