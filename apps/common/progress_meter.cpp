// The progress bar: ETA from the wall time per simulated second so far.
#include "progress_meter.hpp"

#include <unistd.h>

#include <algorithm>

namespace fsi::app {

namespace {
double seconds_between(std::chrono::steady_clock::time_point a,
                       std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}
}  // namespace

ProgressMeter::ProgressMeter(double start_s, double end_s, bool quiet, std::FILE* out)
    : start_s_(start_s),
      end_s_(end_s),
      quiet_(quiet),
      terminal_(isatty(fileno(out)) != 0),
      out_(out),
      wall_start_(std::chrono::steady_clock::now()),
      last_print_(wall_start_) {}

std::string ProgressMeter::duration_text(double seconds) {
  const long s = std::max(0L, static_cast<long>(seconds + 0.5));
  char text[32];
  if (s >= 3600) {
    std::snprintf(text, sizeof text, "%ldh%02ldm", s / 3600, (s % 3600) / 60);
  } else if (s >= 60) {
    std::snprintf(text, sizeof text, "%ldm%02lds", s / 60, s % 60);
  } else {
    std::snprintf(text, sizeof text, "%lds", s);
  }
  return text;
}

void ProgressMeter::update(double t_s, long step, long unconverged) {
  if (quiet_) return;
  const auto now = std::chrono::steady_clock::now();
  const double span = std::max(end_s_ - start_s_, 1e-300);
  const double fraction = std::clamp((t_s - start_s_) / span, 0.0, 1.0);
  const double elapsed = seconds_between(wall_start_, now);
  const std::string eta =
      fraction > 0 ? duration_text(elapsed * (1.0 - fraction) / fraction) : std::string("?");
  char tail[160];
  std::snprintf(tail, sizeof tail, "t=%.3f/%.3f s step %ld ETA %s%s", t_s, end_s_, step,
                eta.c_str(),
                unconverged > 0 ? (" unconverged " + std::to_string(unconverged)).c_str() : "");
  if (terminal_) {
    // At most 10 redraws per second: a terminal is slow to scroll, we are not.
    if (bar_shown_ && seconds_between(last_print_, now) < 0.1 && fraction < 1.0) return;
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(fraction * kWidth);
    std::fprintf(out_, "\r[%s%s] %s\033[K", std::string(filled, '#').c_str(),
                 std::string(kWidth - filled, '.').c_str(), tail);
    bar_shown_ = true;
  } else {
    const int decile = static_cast<int>(fraction * 10 + 1e-9);  // 0.0999../0.1 is 10%
    if (decile == last_decile_ && seconds_between(last_print_, now) < 30.0) return;
    last_decile_ = decile;
    std::fprintf(out_, "%3.0f%% %s\n", 100 * fraction, tail);
  }
  std::fflush(out_);
  last_print_ = now;
}

void ProgressMeter::clear_bar() {
  if (bar_shown_) std::fprintf(out_, "\r\033[K");
  bar_shown_ = false;
}

void ProgressMeter::note(const std::string& line) {
  if (terminal_) clear_bar();
  std::fprintf(out_, "%s\n", line.c_str());
  std::fflush(out_);
}

void ProgressMeter::finish() {
  if (bar_shown_) std::fprintf(out_, "\n");
  bar_shown_ = false;
  std::fflush(out_);
}

}  // namespace fsi::app
