// The typeface behind every label: DejaVu Sans through FreeType, its glyph atlas, and
// the antialiased text it gives a picture.
#include "font.hpp"

#include <gtest/gtest.h>

#include <fsi/renderer.hpp>
#include <fsi/sample_field.hpp>
#include <set>
#include <string>

#include "canvas.hpp"
#include "glyph_atlas.hpp"

namespace fsi::render::detail {
namespace {

TEST(Font, AMissingFontFileIsNamedInTheError) {
  try {
    Font f("/nonexistent/fonts/NoSuchFont.ttf");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("/nonexistent/fonts/NoSuchFont.ttf"), std::string::npos) << what;
    EXPECT_NE(what.find("fonts-dejavu-core"), std::string::npos) << what;
  }
}

TEST(Font, DecodesUtf8AndMarksBrokenBytes) {
  EXPECT_EQ(decode_utf8("a\xE2\x88\x92"
                        "b"),
            (std::u32string{U'a', 0x2212, U'b'}));
  EXPECT_EQ(decode_utf8("\xCE\xBC"
                        "m"),
            (std::u32string{0x3BC, U'm'}));  // micro
  EXPECT_EQ(decode_utf8("x\xFFy"), (std::u32string{U'x', 0xFFFD, U'y'}));
  EXPECT_EQ(decode_utf8("\xE2\x88"), (std::u32string{0xFFFD, 0xFFFD}));  // cut short
}

TEST(Font, DejaVuSansMetrics) {
  const Font& f = default_font();
  // DejaVu Sans: capitals 0.729 em, digits all 0.636 em wide (tabular), so tick labels
  // line up.
  EXPECT_NEAR(f.cap_height_em(), 0.729, 0.01);
  EXPECT_NEAR(f.advance_em(U'0'), 0.636, 0.01);
  EXPECT_FLOAT_EQ(f.advance_em(U'0'), f.advance_em(U'8'));
  EXPECT_FLOAT_EQ(f.advance_em(0x2212), f.advance_em(U'+'));  // minus as wide as plus
  EXPECT_EQ(f.drawable(0x1F600), U'?');                       // no emoji: '?'
  EXPECT_FLOAT_EQ(f.width_em(U"ab"), f.advance_em(U'a') + f.advance_em(U'b'));
}

TEST(GlyphAtlas, RasterizedOncePerSizeAntialiasedAndPacked) {
  const GlyphAtlas& a = glyph_atlas(24);
  EXPECT_EQ(&a, &glyph_atlas(24));
  EXPECT_NE(&a, &glyph_atlas(25));
  const AtlasGlyph& h = a.glyph(U'H');
  // Capitals 0.729 em: 17-18 px at 24 px per em, on the baseline.
  EXPECT_NEAR(h.height, 17.5, 1.0);
  EXPECT_EQ(h.top, h.height);
  std::set<int> levels;
  const AtlasGlyph& o = a.glyph(U'o');
  for (int y = 0; y < o.height; ++y) {
    for (int x = 0; x < o.width; ++x)
      levels.insert(a.coverage()[std::size_t(o.y + y) * a.width() + o.x + x]);
  }
  EXPECT_GT(levels.size(), 20u) << "a round glyph has many grey levels on its edge";
  // Glyphs do not overlap: every printable ASCII glyph's box is disjoint from 'H's.
  for (char32_t c = U'!'; c <= U'~'; ++c) {
    if (c == U'H') continue;
    const AtlasGlyph& g = a.glyph(c);
    const bool apart = g.x + g.width <= h.x || h.x + h.width <= g.x || g.y + g.height <= h.y ||
                       h.y + h.height <= g.y;
    EXPECT_TRUE(apart) << "glyph U+" << std::hex << unsigned(c) << " overlaps 'H'";
  }
}

TEST(CanvasText, WidthScalesWithTheSizeAndIgnoresSupersampling) {
  EXPECT_NEAR(Canvas::text_width("t = 1.234 s", 2.0f),
              2.0f * Canvas::text_width("t = 1.234 s", 1.0f), 1e-4);
  EXPECT_EQ(Canvas::text_width("", 2.0f), 0.0f);
}

TEST(CanvasText, TitleIsAntialiasedInk) {
  // The title row of a frame holds dark ink, white paper and the grey levels between
  // them that an antialiased font leaves on its edges.
  Renderer r{GlBackend::osmesa};
  FrameSpec s;
  s.width = 640;
  s.height = 360;
  s.title = "Ball drop";
  s.show_colorbar = false;
  const Image im = r.render(sample_field_view(), s);
  std::set<int> greys;
  int dark = 0;
  for (int y = 0; y < im.height / 12; ++y) {
    for (int x = 0; x < im.width; ++x) {
      const std::uint8_t* p = &im.rgba[im.offset(x, y)];
      if (p[0] == p[1] && p[1] == p[2]) greys.insert(p[0]);
      dark += p[0] < 60;
    }
  }
  EXPECT_GT(dark, 50);
  EXPECT_GT(greys.size(), 30u);
}

}  // namespace
}  // namespace fsi::render::detail
