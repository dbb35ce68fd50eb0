// fsi-plot: curves from functionals CSV files (fsi-movie's functionals.csv) in one PNG,
// like the chapter's Figs. 12.7, 12.8 and 12.12.
//
//   fsi-plot OUT.png --x COLUMN --y COLUMN [--title T] [--ylabel L] [--logy]
//            [--xmin A] [--xmax B] [--skip-above COLUMN=VALUE ...] CSV1[:label1] ...
//
// Rows whose value does not parse (or is empty) break the curve. --skip-above leaves out
// the rows whose COLUMN exceeds VALUE, e.g. --skip-above mass_error=0.5: the degenerated
// last step of a run fsi-movie stopped (it would draw a spike). Exit 0 on success, 2 on
// bad input (missing file or column).
//
// Example:
//   fsi-plot out/study-contact/distance.png --x time_s --y min_distance_m --logy
//     out/study-contact/d0_1e-2_g800/functionals.csv:"d0 = 1e-2, g = 800"
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fsi/plot.hpp>
#include <fsi/png.hpp>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

int usage(const std::string& why) {
  std::fprintf(stderr,
               "fsi-plot: %s\nusage: fsi-plot OUT.png --x COLUMN --y COLUMN [--title T] [--ylabel L] "
               "[--logy] [--xmin A] [--xmax B] [--skip-above COLUMN=VALUE ...] CSV[:label] ...\n",
               why.c_str());
  return 2;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

double number(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  return end != text.c_str() && *end == '\0' ? v : std::numeric_limits<double>::quiet_NaN();
}

/// Rows whose `column` exceeds `limit` are left out.
struct SkipAbove {
  std::string column;
  double limit;
};

/// One curve: columns x and y of a CSV file with a header line.
fsi::render::PlotSeries read_series(const std::string& file, const std::string& label,
                                    const std::string& x_col, const std::string& y_col,
                                    const std::vector<SkipAbove>& skips) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file);
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(file + " is empty");
  const std::vector<std::string> header = split(line);
  int ix = -1, iy = -1;
  for (int i = 0; i < static_cast<int>(header.size()); ++i) {
    if (header[i] == x_col) ix = i;
    if (header[i] == y_col) iy = i;
  }
  if (ix < 0 || iy < 0) throw std::runtime_error(file + " has no column " + (ix < 0 ? x_col : y_col));
  std::vector<std::pair<int, double>> skip_columns;
  for (const SkipAbove& skip : skips) {
    const auto it = std::find(header.begin(), header.end(), skip.column);
    if (it == header.end()) throw std::runtime_error(file + " has no column " + skip.column + " (--skip-above)");
    skip_columns.emplace_back(static_cast<int>(it - header.begin()), skip.limit);
  }
  fsi::render::PlotSeries s{label, {}, {}};
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = split(line);
    const auto cell = [&](int i) { return i < static_cast<int>(cells.size()) ? number(cells[i]) : number(""); };
    if (std::any_of(skip_columns.begin(), skip_columns.end(),
                    [&](const auto& c) { return cell(c.first) > c.second; }))
      continue;
    s.x.push_back(cell(ix));
    s.y.push_back(cell(iy));
  }
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage("needs an output file");
  fsi::render::PlotSpec spec;
  std::string x_col, y_col;
  std::vector<std::string> inputs;
  std::vector<SkipAbove> skips;
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--logy") {
      spec.log_y = true;
    } else if (arg.rfind("--", 0) == 0) {
      if (!has_value) return usage("missing value after " + arg);
      const std::string value = argv[++i];
      if (arg == "--x") x_col = value;
      else if (arg == "--y") y_col = value;
      else if (arg == "--title") spec.title = value;
      else if (arg == "--ylabel") spec.y_label = value;
      else if (arg == "--xmin") spec.x_min = number(value);
      else if (arg == "--xmax") spec.x_max = number(value);
      else if (arg == "--skip-above") {
        const std::size_t eq = value.find('=');
        const double limit = eq == std::string::npos ? number("") : number(value.substr(eq + 1));
        if (eq == 0 || limit != limit) return usage("--skip-above wants COLUMN=NUMBER, got '" + value + "'");
        skips.push_back({value.substr(0, eq), limit});
      }
      else return usage("unknown option " + arg);
    } else {
      inputs.push_back(arg);
    }
  }
  if (x_col.empty() || y_col.empty()) return usage("--x and --y are required");
  if (inputs.empty()) return usage("no CSV files");
  if (spec.y_label.empty()) spec.y_label = y_col;
  spec.x_label = x_col;
  try {
    for (const std::string& input : inputs) {
      // FILE:label; a ':' inside the path is kept when no label follows.
      const std::size_t colon = input.find(".csv:");
      const std::string file = colon == std::string::npos ? input : input.substr(0, colon + 4);
      const std::string label = colon == std::string::npos ? file : input.substr(colon + 5);
      spec.series.push_back(read_series(file, label, x_col, y_col, skips));
    }
    fsi::render::write_png(argv[1], fsi::render::plot(spec));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fsi-plot: %s\n", e.what());
    return 2;
  }
  std::printf("wrote %s (%zu curves)\n", argv[1], spec.series.size());
  return 0;
}
