#pragma once
// Canvas: 2D drawing in *logical pixels* (origin top left, y down) on a RenderContext.
// The GL framebuffer is `supersample` times larger in each direction (1 by default) and
// the projection maps logical pixels onto it with the top row first in memory, so the
// read-back needs no flip. Edges are antialiased per primitive: lines get a one-pixel
// alpha fringe, text comes from an antialiased glyph atlas, axis-aligned bars and rules
// are snapped to whole pixels; supersampling (box filter in finish()) smooths the rest.
#include <array>
#include <cstdint>
#include <map>
#include <string_view>
#include <vector>

#include "fsi/colormap.hpp"
#include "fsi/image.hpp"
#include "fsi/render_context.hpp"
#include "gl_api.hpp"

namespace fsi::render::detail {

struct Vec2 {
  float x = 0, y = 0;  ///< [logical px]
};

struct Rgba {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
};

struct Rect {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< [logical px], x0 < x1, y0 < y1 (top < bottom)
  float width() const { return x1 - x0; }
  float height() const { return y1 - y0; }
};

enum class Align { start, centre, end };

class Canvas {
 public:
  /// Creates the GL resources in `context` (kept by reference; must outlive the canvas).
  explicit Canvas(RenderContext& context);
  ~Canvas();
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;

  /// Starts a picture of width x height logical px filled with `background`.
  /// \param supersample framebuffer pixels per logical pixel per direction (1..4)
  void begin(int width, int height, int supersample, Rgba background = {255, 255, 255, 255});
  /// Reads the framebuffer back into `out` (resized; its storage is reused when the
  /// size is unchanged) and box-filters it down when supersampling.
  void finish(Image& out);
  Image finish() {
    Image out;
    finish(out);
    return out;
  }

  int width() const { return width_; }
  int height() const { return height_; }

  /// Restricts drawing to `r` until clear_clip().
  void clip(const Rect& r);
  void clear_clip();

  void fill_rect(const Rect& r, Rgba colour);
  void stroke_rect(const Rect& r, float line_width, Rgba colour);
  /// Separate segments: points[2k] -> points[2k+1]. Thick lines are quads; with
  /// round_joins a small disc at each end hides the notches where segments meet.
  void segments(const std::vector<Vec2>& points, float line_width, Rgba colour,
                bool round_joins = false);
  /// A connected polyline through `points`.
  void polyline(const std::vector<Vec2>& points, float line_width, Rgba colour);

  /// Triangles coloured by a scalar: `t` in [0, 1] per vertex is interpolated by GL and
  /// looked up per pixel in the colour map (values outside saturate at the ends).
  void scalar_triangles(const std::vector<Vec2>& positions, const std::vector<float>& t,
                        const std::vector<unsigned>& indices, Colormap map);
  /// An axis-aligned rectangle whose colour runs through the whole map from the
  /// bottom (low) to the top (high): the colour bar.
  void colormap_rect(const Rect& r, Colormap map);

  /// Text (UTF-8) in DejaVu Sans (font.hpp). `scale` 1 gives 7 px tall capitals. (x, y)
  /// is the anchor; h/v say which side of the text it is on (v: start = top of
  /// capitals, end = baseline). vertical text reads bottom to top (a y-axis label).
  void text(std::string_view s, float x, float y, float scale, Rgba colour, Align h = Align::start,
            Align v = Align::start, bool vertical = false);
  /// Width of a string at `scale` [logical px].
  static float text_width(std::string_view s, float scale);
  /// Height of capitals at `scale` [logical px].
  static float text_height(float scale) { return 7.0f * scale; }

 private:
  struct ColouredVertex {
    float x, y;
    std::uint8_t r, g, b, a;
  };
  void triangles(const std::vector<Vec2>& vertices, Rgba colour);
  void coloured_triangles(const std::vector<ColouredVertex>& vertices);
  /// A rectangle with its edges rounded to whole framebuffer pixels (at least one wide).
  Rect snapped(const Rect& r) const;
  /// A bar of `w` logical px centred on the line x = c (vertical) or y = c, snapped.
  Rect snapped_bar(float c, float from, float to, float w, bool vertical) const;
  void set_blending(bool on);
  unsigned texture(Colormap map);
  unsigned glyph_texture(int pixel_size);

  RenderContext& context_;
  GlApi gl_;
  int width_ = 0, height_ = 0, supersample_ = 1;
  bool blending_ = false;
  std::array<unsigned, 2> textures_{};      // one 1D texture per Colormap, made on first use
  std::map<int, unsigned> glyph_textures_;  // glyph atlas per pixel size, made on first use
  // Scratch buffers kept between frames: no allocation per frame once they have grown.
  std::vector<std::uint8_t> framebuffer_;  // supersampled read-back
  std::vector<Vec2> vertices_;
  std::vector<ColouredVertex> coloured_;
  std::vector<float> texcoords_;
};

}  // namespace fsi::render::detail
