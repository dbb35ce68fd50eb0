#pragma once
// The typeface every label is set in: DejaVu Sans, read and rasterized by FreeType.
// Layout uses the unhinted advances in ems, so a string's width does not depend on the
// pixel size it is drawn at (a supersampled frame is laid out like a plain one).
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace fsi::render::detail {

/// Where Debian's fonts-dejavu-core puts the font.
inline constexpr const char* default_font_file = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

/// One glyph as 8-bit coverage (0 = paper, 255 = ink), rows top first.
struct GlyphBitmap {
  int width = 0, height = 0;           ///< [px]
  int left = 0;                        ///< pen position to the bitmap's left edge [px]
  int top = 0;                         ///< baseline up to the bitmap's top row [px]
  std::vector<std::uint8_t> coverage;  ///< width * height
};

/// The characters the atlas holds: printable ASCII, Latin-1, Greek and a few symbols
/// (en dash, ellipsis, minus sign, ...). Others are drawn as '?'.
const std::vector<char32_t>& font_charset();

/// UTF-8 to code points; a malformed byte becomes U+FFFD (drawn as '?').
std::u32string decode_utf8(std::string_view text);

class Font {
 public:
  /// Opens a TrueType/OpenType file. Throws std::runtime_error naming the file when it
  /// is missing or FreeType cannot read it.
  explicit Font(const std::filesystem::path& file);
  ~Font();
  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;

  /// Horizontal advance [em] of `c` ('?' for characters outside font_charset()).
  float advance_em(char32_t c) const;
  /// Height of the capitals (from the glyph 'H') [em].
  float cap_height_em() const { return cap_height_em_; }
  /// Width of a decoded string [em].
  float width_em(std::u32string_view text) const;

  /// Antialiased bitmap of `c` at `pixel_size` px per em (light hinting: vertical only,
  /// so advances keep their unhinted widths). Thread-safe.
  GlyphBitmap rasterize(char32_t c, int pixel_size) const;

  /// The character drawn for `c`: itself when in font_charset(), else '?'.
  char32_t drawable(char32_t c) const { return advances_.count(c) ? c : U'?'; }

 private:
  std::filesystem::path file_;
  void* library_ = nullptr;  // FT_Library (FreeType's types stay out of this header)
  void* face_ = nullptr;     // FT_Face
  std::unordered_map<char32_t, float> advances_;  // [em], every character of the charset
  float cap_height_em_ = 0.7f;
  mutable std::mutex mutex_;  // a FreeType face is not safe for concurrent use
};

/// The process-wide DejaVu Sans (default_font_file), opened on first use.
/// Throws std::runtime_error naming the file (and the Debian package) when missing.
const Font& default_font();

}  // namespace fsi::render::detail
