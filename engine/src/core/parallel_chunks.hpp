#pragma once
/// \file parallel_chunks.hpp
/// Runs f(begin, end) over [0, n) split into `threads` contiguous chunks, the first on the
/// calling thread, the others on threads of their own, and waits for all of them.
///
/// The callers make each chunk write memory no other chunk writes (patches of one colour
/// share no node: mesh::colour_patches), so the result does not depend on how many
/// threads ran or in which order they finished: the same bits for any thread count.
#include <algorithm>
#include <thread>
#include <vector>

namespace fsi::core {

template <class F>
void parallel_chunks(int threads, int n, const F& f) {
  threads = std::max(1, std::min(threads, n));
  if (threads == 1) {
    if (n > 0) f(0, n);
    return;
  }
  std::vector<std::thread> workers;
  workers.reserve(static_cast<std::size_t>(threads - 1));
  for (int t = 1; t < threads; ++t)
    workers.emplace_back([&f, t, threads, n] {
      f(static_cast<int>(static_cast<long>(n) * t / threads), static_cast<int>(static_cast<long>(n) * (t + 1) / threads));
    });
  f(0, static_cast<int>(static_cast<long>(n) / threads));
  for (std::thread& w : workers) w.join();
}

/// The threads a numerics.assembly_threads setting asks for: itself when positive, else
/// the machine's hardware threads (at least 1, at most 8: the element loop of the
/// 66049-node mesh has 16384 patches, and past a few threads the serial parts dominate).
inline int resolve_threads(int setting) {
  if (setting > 0) return setting;
  const unsigned hardware = std::thread::hardware_concurrency();
  return std::clamp(static_cast<int>(hardware), 1, 8);
}

}  // namespace fsi::core
