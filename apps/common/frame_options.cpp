// Parsers for the picture options: whole-text parses, messages that say what is allowed.
#include "frame_options.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fsi/error.hpp>
#include <stdexcept>

namespace fsi::app {

render::Quantity parse_field(const std::string& text, const std::string& origin,
                             const std::string& option) {
  try {
    return render::parse_quantity(text);
  } catch (const std::invalid_argument&) {
    throw InputError(origin, option, "must be one of vx, vy, vmag, p, umag, got '" + text + "'");
  }
}

double parse_number(const std::string& text, const std::string& origin, const std::string& option) {
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v)) {
    throw InputError(origin, option, "must be a number, got '" + text + "'");
  }
  return v;
}

int parse_int(const std::string& text, long lo, long hi, const std::string& origin,
              const std::string& option) {
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || v < lo || v > hi) {
    throw InputError(origin, option,
                     "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                         "], got '" + text + "'");
  }
  return static_cast<int>(v);
}

render::ViewWindow parse_zoom(const std::string& text, const std::string& origin,
                              const std::string& option) {
  double c[4];
  std::size_t start = 0;
  for (int i = 0; i < 4; ++i) {
    const std::size_t comma = text.find(',', start);
    if ((i < 3) != (comma != std::string::npos)) {
      throw InputError(origin, option, "wants x0,y0,x1,y1 in metres, got '" + text + "'");
    }
    c[i] = parse_number(text.substr(start, comma - start), origin, option);
    start = comma + 1;
  }
  if (!(c[0] < c[2] && c[1] < c[3])) {
    throw InputError(origin, option, "wants x0 < x1 and y0 < y1, got '" + text + "'");
  }
  return {c[0], c[1], c[2], c[3]};
}

void parse_size(const std::string& text, const std::string& origin, const std::string& option,
                int& width, int& height) {
  const std::size_t x = text.find('x');
  if (x == std::string::npos) {
    throw InputError(origin, option,
                     "wants WIDTHxHEIGHT in pixels, e.g. 1280x720, got '" + text + "'");
  }
  width = parse_int(text.substr(0, x), 16, 8192, origin, option);
  height = parse_int(text.substr(x + 1), 16, 8192, origin, option);
}

std::string option_value(int& i, int argc, char** argv) {
  if (i + 1 >= argc) throw InputError("command line", argv[i], "needs a value");
  return argv[++i];
}

}  // namespace fsi::app
