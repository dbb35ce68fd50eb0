// fsi-imgdiff: compares two PNGs by decoded pixels, as the image regression tests do.
//
//   fsi-imgdiff EXPECTED.png ACTUAL.png [--max-bad-fraction F] [--threshold T] [--diff OUT.png]
//
// A pixel is bad when some channel differs by more than T (0..255, default 8); the
// images are the same when at most a fraction F (default 0.005) of pixels is bad.
// Prints one verdict line. Exit code: 0 same, 1 differ, 2 bad input (missing file,
// not a PNG, sizes differ, bad option).
//
// Examples:
//   fsi-imgdiff tests/golden/plot_log.png build/image-test-output/plot_log.actual.png
//   fsi-imgdiff a.png b.png --threshold 0 --max-bad-fraction 0 --diff diff.png
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fsi/image_compare.hpp>
#include <fsi/png.hpp>
#include <string>

namespace {

constexpr int exit_same = 0, exit_differ = 1, exit_bad_input = 2;

int usage(const char* why) {
  std::fprintf(stderr,
               "fsi-imgdiff: %s\n"
               "usage: fsi-imgdiff EXPECTED.png ACTUAL.png [--max-bad-fraction F] "
               "[--threshold T] [--diff OUT.png]\n",
               why);
  return exit_bad_input;
}

// Parses the whole of `text` as a number, or returns false.
bool parse_number(const char* text, double& out) {
  char* end = nullptr;
  out = std::strtod(text, &end);
  return end != text && *end == '\0';
}

}  // namespace

int main(int argc, char** argv) {
  std::string files[2], diff_file;
  int n_files = 0;
  double max_bad = 0.005, threshold = 8;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-h" || a == "--help") {
      usage("compare two PNG images");
      return exit_same;
    }
    if (a == "--max-bad-fraction" || a == "--threshold" || a == "--diff") {
      if (i + 1 >= argc) return usage((a + " needs a value").c_str());
      const char* v = argv[++i];
      if (a == "--diff") {
        diff_file = v;
      } else if (a == "--threshold") {
        if (!parse_number(v, threshold) || threshold < 0 || threshold > 255) {
          return usage("--threshold must be a number in [0, 255]");
        }
      } else if (!parse_number(v, max_bad) || max_bad < 0 || max_bad > 1) {
        return usage("--max-bad-fraction must be a number in [0, 1]");
      }
    } else if (!a.empty() && a[0] == '-') {
      return usage(("unknown option " + a).c_str());
    } else if (n_files < 2) {
      files[n_files++] = a;
    } else {
      return usage("more than two images given");
    }
  }
  if (n_files != 2) return usage("need EXPECTED.png and ACTUAL.png");
  try {
    const auto expected = fsi::render::read_png(files[0]);
    const auto actual = fsi::render::read_png(files[1]);
    const auto r = fsi::render::compare_images(expected, actual, int(threshold), max_bad);
    if (!diff_file.empty()) fsi::render::write_png(diff_file, r.diff);
    std::printf("%s\n", r.verdict.c_str());
    return r.same ? exit_same : exit_differ;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fsi-imgdiff: %s\n", e.what());
    std::printf("error: %s\n", e.what());
    return exit_bad_input;
  }
}
