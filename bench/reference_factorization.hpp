#pragma once
// The unit in which the benchmarks report wall time: one reference LU factorization.
//
// The machines here are shared and their speed drifts, so a time means something only
// against another time measured in the same process. The reference is a numeric
// factorization by UMFPACK (one BLAS thread: run with OPENBLAS_NUM_THREADS=1) of a
// 5-field matrix with the 9-point node stencil on an n x n node grid (every unknown of a
// node coupled to every unknown of itself and of its 8 neighbours), random off-diagonal
// values in [-1, 1] from a fixed seed and a dominant diagonal, UMFPACK's default
// ordering, the symbolic analysis done once and not timed. It is the size of the
// engine's 4225-node system at n = 65 and of the 16641-node one at n = 129.
#include <umfpack.h>

#include "cpu_seconds.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace fsi::bench {

class ReferenceFactorization {
 public:
  explicit ReferenceFactorization(int nodes_per_side) : n_(nodes_per_side) {
    constexpr int kFields = 5;
    const int nodes = n_ * n_, size = kFields * nodes;
    std::uint64_t seed = 0x9e3779b97f4a7c15ULL;
    const auto random_unit = [&seed] {  // xorshift64*: [-1, 1]
      seed ^= seed >> 12, seed ^= seed << 25, seed ^= seed >> 27;
      return double((seed * 0x2545f4914f6cdd1dULL) >> 11) * 0x1.0p-53 * 2.0 - 1.0;
    };
    // Column-major: column (node b, field fb) holds the rows of b's neighbours a, sorted.
    col_start_.assign(size + 1, 0);
    for (int bj = 0; bj < n_; ++bj)
      for (int bi = 0; bi < n_; ++bi)
        for (int fb = 0; fb < kFields; ++fb) {
          const int col = kFields * (bj * n_ + bi) + fb;
          for (int aj = std::max(0, bj - 1); aj <= std::min(n_ - 1, bj + 1); ++aj)
            for (int ai = std::max(0, bi - 1); ai <= std::min(n_ - 1, bi + 1); ++ai)
              for (int fa = 0; fa < kFields; ++fa) {
                const int row = kFields * (aj * n_ + ai) + fa;
                row_.push_back(row);
                value_.push_back(row == col ? 0.0 : random_unit());
              }
          col_start_[col + 1] = static_cast<int>(row_.size());
        }
    // A dominant diagonal: the largest column sum of |off-diagonal| plus one.
    double largest = 0.0;
    for (int c = 0; c < size; ++c) {
      double sum = 0.0;
      for (int k = col_start_[c]; k < col_start_[c + 1]; ++k) sum += std::abs(value_[k]);
      largest = std::max(largest, sum);
    }
    for (int c = 0; c < size; ++c)
      for (int k = col_start_[c]; k < col_start_[c + 1]; ++k)
        if (row_[k] == c) value_[k] = largest + 1.0;
    double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
    umfpack_di_defaults(control);
    if (umfpack_di_symbolic(size, size, col_start_.data(), row_.data(), value_.data(), &symbolic_, control, info) !=
        UMFPACK_OK)
      throw std::runtime_error("reference factorization: symbolic analysis failed");
  }
  ~ReferenceFactorization() { umfpack_di_free_symbolic(&symbolic_); }
  ReferenceFactorization(const ReferenceFactorization&) = delete;
  ReferenceFactorization& operator=(const ReferenceFactorization&) = delete;

  /// Seconds of one numeric factorization, wall and CPU, each the median of `repeats`.
  struct Timing {
    double wall_s = 0.0, cpu_s = 0.0;
  };
  Timing time(int repeats = 5) {
    std::vector<double> wall, cpu;
    for (int i = 0; i < repeats; ++i) {
      double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
      umfpack_di_defaults(control);
      void* numeric = nullptr;
      const auto t0 = std::chrono::steady_clock::now();
      const double c0 = cpu_seconds();
      const int status =
          umfpack_di_numeric(col_start_.data(), row_.data(), value_.data(), symbolic_, &numeric, control, info);
      cpu.push_back(cpu_seconds() - c0);
      wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      umfpack_di_free_numeric(&numeric);
      if (status != UMFPACK_OK) throw std::runtime_error("reference factorization: numeric phase failed");
    }
    std::sort(wall.begin(), wall.end());
    std::sort(cpu.begin(), cpu.end());
    return {wall[wall.size() / 2], cpu[cpu.size() / 2]};
  }
  /// Wall seconds of one numeric factorization: the median of `repeats`.
  double seconds(int repeats = 5) { return time(repeats).wall_s; }
  int nodes_per_side() const { return n_; }

 private:
  int n_;
  std::vector<int> col_start_, row_;
  std::vector<double> value_;
  void* symbolic_ = nullptr;
};

}  // namespace fsi::bench
