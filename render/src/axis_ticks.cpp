#include "fsi/axis_ticks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fsi::render {

double nice_step(double lo, double hi, int target) {
  const double span = std::abs(hi - lo);
  if (!(span > 0) || !std::isfinite(span)) return 1.0;
  const double raw = span / std::max(target, 1);
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / decade;  // in [1, 10)
  const double m = f < 1.5 ? 1.0 : f < 3.0 ? 2.0 : f < 7.0 ? 5.0 : 10.0;
  return m * decade;
}

std::vector<double> nice_ticks(double lo, double hi, int target) {
  if (lo > hi) std::swap(lo, hi);
  const double step = nice_step(lo, hi, target);
  std::vector<double> ticks;
  const double eps = 1e-9 * step;
  for (double k = std::ceil((lo - eps) / step); k * step <= hi + eps; k += 1.0) {
    const double v = k * step;
    ticks.push_back(std::abs(v) < eps ? 0.0 : v);  // never "-0"
    if (ticks.size() > 100) break;                 // defensive: absurd target
  }
  return ticks;
}

std::vector<double> log_ticks(double lo, double hi, int target) {
  std::vector<double> ticks;
  if (!(lo > 0) || !(hi > lo)) return ticks;
  const int k0 = int(std::floor(std::log10(lo))), k1 = int(std::ceil(std::log10(hi)));
  const int every = std::max(1, (k1 - k0 + target - 1) / std::max(target, 1));
  // Decades alone when there are enough of them; else 1-2-5, then every integer
  // multiple, so even a short log axis carries at least two labelled ticks.
  for (const std::vector<double>& mantissas :
       {std::vector<double>{1}, {1, 2, 5}, {1, 2, 3, 4, 5, 6, 7, 8, 9}}) {
    ticks.clear();
    for (int k = k0; k <= k1; ++k) {
      if (mantissas.size() == 1 && (k - k0) % every != 0) continue;
      for (double m : mantissas) {
        const double v = m * std::pow(10.0, k);
        if (v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9)) ticks.push_back(v);
      }
    }
    if (ticks.size() >= 3) break;
  }
  return ticks;
}

std::string format_tick(double value, double step) {
  char buf[64];
  const double mag = std::max(std::abs(value), std::abs(step));
  step = std::abs(step) > 0 ? std::abs(step) : mag;
  if (mag >= 1e5 || mag < 1e-3) {
    if (value == 0.0) return "0";
    // Enough mantissa digits to tell neighbouring ticks apart.
    const int digits = std::clamp(int(std::ceil(std::log10(mag / step) - 1e-9)), 0, 6);
    std::snprintf(buf, sizeof buf, "%.*e", digits, value);
    return buf;
  }
  const int decimals = std::clamp(int(std::ceil(-std::log10(step) - 1e-9)), 0, 10);
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  return buf;
}

}  // namespace fsi::render
