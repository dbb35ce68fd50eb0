// fsi-contact-sheet: six (or COLSxROWS) frames of a run on one picture, for the docs or
// a slide: picked evenly from the inputs (the first and the last included), shrunk by
// area averaging, tiled in reading order.
//
//   fsi-contact-sheet OUT.png FRAMES... [--grid COLSxROWS] [--tile-width PX]
//
// FRAMES are PNG files or folders (each folder's *.png, sorted by name: a run's
// frames/). Defaults: --grid 3x2, --tile-width 480. Exit code 0, or 2 on bad input
// (message + usage).
//
// Examples:
//   fsi-contact-sheet docs/images/demo_contact_sheet.png out/demo/frames
//   fsi-contact-sheet sheet.png a.png b.png c.png d.png --grid 2x2 --tile-width 640
#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fsi/contact_sheet.hpp>
#include <fsi/png.hpp>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

constexpr const char* kUsage =
    "usage: fsi-contact-sheet OUT.png FRAMES... [--grid COLSxROWS] [--tile-width PX]\n"
    "  FRAMES: PNG files or folders of them (e.g. a run's frames/)\n";

int usage(const std::string& why) {
  std::fprintf(stderr, "fsi-contact-sheet: %s\n%s", why.c_str(), kUsage);
  return 2;
}

bool parse_positive(const std::string& text, int& value) {
  try {
    std::size_t used = 0;
    value = std::stoi(text, &used);
    return used == text.size() && value >= 1 && value <= 8192;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

int main(int argc, char** argv) {
  int cols = 3, rows = 2, tile_width = 480;
  std::vector<std::string> positional;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-h" || a == "--help") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (a == "--grid" || a == "--tile-width") {
      if (i + 1 >= argc) return usage(a + " needs a value");
      const std::string v = argv[++i];
      if (a == "--tile-width") {
        if (!parse_positive(v, tile_width))
          return usage("--tile-width wants pixels, got '" + v + "'");
      } else {
        const std::size_t x = v.find('x');
        if (x == std::string::npos || !parse_positive(v.substr(0, x), cols) ||
            !parse_positive(v.substr(x + 1), rows)) {
          return usage("--grid wants COLSxROWS, e.g. 3x2, got '" + v + "'");
        }
      }
    } else if (a.size() > 1 && a[0] == '-') {
      return usage("unknown option " + a);
    } else {
      positional.push_back(a);
    }
  }
  if (positional.size() < 2) return usage("need OUT.png and at least one frame");
  std::vector<fs::path> files;
  for (std::size_t i = 1; i < positional.size(); ++i) {
    const fs::path p = positional[i];
    if (fs::is_directory(p)) {
      std::vector<fs::path> in_dir;
      for (const auto& e : fs::directory_iterator(p)) {
        if (e.path().extension() == ".png") in_dir.push_back(e.path());
      }
      std::sort(in_dir.begin(), in_dir.end());
      files.insert(files.end(), in_dir.begin(), in_dir.end());
    } else if (fs::exists(p)) {
      files.push_back(p);
    } else {
      return usage("no such file or folder: " + p.string());
    }
  }
  if (files.empty()) return usage("no PNG frames found");
  try {
    std::vector<fsi::render::Image> frames;
    for (std::size_t k : fsi::render::evenly_spaced(files.size(), std::size_t(cols) * rows)) {
      frames.push_back(fsi::render::read_png(files[k]));
    }
    const fsi::render::Image sheet = fsi::render::contact_sheet(frames, cols, tile_width);
    // The smallest file: a sheet is written once and may be kept in the repository.
    fsi::render::write_png(positional[0], sheet, 12);
    std::printf("wrote %s (%dx%d, %zu of %zu frames)\n", positional[0].c_str(), sheet.width,
                sheet.height, frames.size(), files.size());
    return 0;
  } catch (const std::exception& e) {
    return usage(e.what());
  }
}
