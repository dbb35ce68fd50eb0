#include "mesh/axis.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fsi::mesh {

std::vector<double> piece_lines(const AxisPiece& piece) {
  const int n = piece.patches;
  const double length = piece.to_m - piece.from_m;
  const double abs_length = std::abs(length);
  const double uniform = abs_length / n;
  const double first = piece.first_m > 0.0 ? piece.first_m : uniform;
  const double last = piece.last_m > 0.0 ? piece.last_m : uniform;
  // c fixes the first patch: x(1/n) - x(0) = L (c/n + (1-c) n^-q) ~ L c / n for q > 1.
  // Solve both ends together: for given q, c = (first/L - n^-q) / (1/n - n^-q); then
  // bisect q so that the last patch matches.
  const double a = first / abs_length;
  auto c_of = [&](double q) {
    const double nq = std::pow(1.0 / n, q);
    const double d = 1.0 / n - nq;
    return std::abs(d) < 1e-300 ? 1.0 : (a - nq) / d;
  };
  auto last_of = [&](double q) {
    const double c = c_of(q);
    const double t = 1.0 - 1.0 / n;
    return abs_length * (1.0 - (c * t + (1.0 - c) * std::pow(t, q)));
  };
  double q = 1.0;
  if (n > 1 && std::abs(first - last) > 1e-14 * abs_length) {
    // last_of is increasing in q for first < last; search q in (0.05, 50).
    double lo = 0.05, hi = 50.0;
    const bool grows = last > first;
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      const bool too_big = last_of(mid) > last;
      if (too_big == grows) hi = mid; else lo = mid;
    }
    q = 0.5 * (lo + hi);
  }
  const double c = n > 1 && q != 1.0 ? c_of(q) : 1.0;
  std::vector<double> x(n + 1);
  for (int i = 0; i <= n; ++i) {
    const double t = static_cast<double>(i) / n;
    x[i] = piece.from_m + length * (c * t + (1.0 - c) * std::pow(t, q));
  }
  x[n] = piece.to_m;
  for (int i = 0; i < n; ++i)
    if (!((x[i + 1] - x[i]) * length > 0.0))
      throw std::invalid_argument("axis piece grading gives a non-positive patch size");
  return x;
}

std::vector<double> axis_lines(const std::vector<AxisPiece>& pieces) {
  std::vector<std::pair<double, double>> ranges;
  std::vector<double> all;
  for (const AxisPiece& p : pieces) {
    std::vector<double> x = piece_lines(p);
    ranges.emplace_back(std::min(p.from_m, p.to_m), std::max(p.from_m, p.to_m));
    all.insert(all.end(), x.begin(), x.end());
  }
  std::sort(ranges.begin(), ranges.end());
  for (std::size_t i = 1; i < ranges.size(); ++i) {
    const double scale = std::max(1.0, std::abs(ranges[i].first));
    if (std::abs(ranges[i].first - ranges[i - 1].second) > 1e-12 * scale)
      throw std::invalid_argument("axis pieces overlap or leave a gap");
  }
  std::sort(all.begin(), all.end());
  std::vector<double> lines;
  for (double v : all)
    if (lines.empty() || v - lines.back() > 1e-12 * std::max(1.0, std::abs(v))) lines.push_back(v);
  return lines;
}

std::vector<double> refine_lines(std::vector<double> lines, int times) {
  for (int r = 0; r < times; ++r) {
    std::vector<double> finer;
    finer.reserve(2 * lines.size());
    for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
      finer.push_back(lines[i]);
      finer.push_back(0.5 * (lines[i] + lines[i + 1]));
    }
    finer.push_back(lines.back());
    lines = std::move(finer);
  }
  return lines;
}

}  // namespace fsi::mesh
