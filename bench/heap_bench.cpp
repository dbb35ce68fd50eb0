// What keeping large blocks in the heap (apps/common/heap_tuning.hpp, used by fsi-movie
// and fsi-step) saves on a mesh whose factorization is larger than glibc's mmap threshold:
// the same steps, first with glibc's defaults, then tuned, in one process.
//
//   build/bench/fsi-bench-heap [SCENARIO.json=assets/scenarios/stairs/stairs_rho300.json]
//                              [steps=10] [CHECKPOINT]
//
// The steps start at t = 0 or at the checkpoint (a stairs run's, where the ball rolls and
// every other step refactorizes several times). Prints the CPU seconds (user + sys) and
// minor page faults of the steps alone and their ratios; compare
// the ratios (the machines here are shared). Run it with OPENBLAS_NUM_THREADS=1 on a busy
// machine, or OpenBLAS's spinning threads dominate the sys time.
#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>
#include <fsi/engine.hpp>
#include <string>

#include "heap_tuning.hpp"

namespace {

struct Usage {
  double cpu_s = 0.0;
  long minor_faults = 0;
};

Usage usage_now() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  const auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
  return {seconds(u.ru_utime) + seconds(u.ru_stime), u.ru_minflt};
}

Usage run(const fsi::Scenario& s, int steps, const std::string& checkpoint, int& factorizations) {
  fsi::Engine engine(s);
  if (!checkpoint.empty()) fsi::load_checkpoint(engine, checkpoint);
  factorizations = 0;
  const Usage before = usage_now();
  for (int i = 0; i < steps; ++i) factorizations += engine.step().factorizations;
  const Usage after = usage_now();
  return {after.cpu_s - before.cpu_s, after.minor_faults - before.minor_faults};
}

}  // namespace

int main(int argc, char** argv) {
  const std::string file = argc > 1 ? argv[1] : "assets/scenarios/stairs/stairs_rho300.json";
  const int steps = argc > 2 ? std::atoi(argv[2]) : 10;
  const std::string checkpoint = argc > 3 ? argv[3] : "";
  if (steps < 1) {
    std::fprintf(stderr, "fsi-bench-heap: steps must be at least 1\n");
    return 2;
  }
  Usage plain, tuned;
  int plain_factorizations = 0, tuned_factorizations = 0;
  try {
    const fsi::Scenario s = fsi::load_scenario(file);
    plain = run(s, steps, checkpoint, plain_factorizations);
    fsi::app::keep_large_blocks_in_heap();
    tuned = run(s, steps, checkpoint, tuned_factorizations);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fsi-bench-heap: %s\n", e.what());
    return 2;
  }
  std::printf("%-22s %10s %14s %15s\n", "", "CPU s", "minor faults", "factorizations");
  std::printf("%-22s %10.2f %14ld %15d\n", "glibc defaults", plain.cpu_s, plain.minor_faults,
              plain_factorizations);
  std::printf("%-22s %10.2f %14ld %15d\n", "large blocks in heap", tuned.cpu_s, tuned.minor_faults,
              tuned_factorizations);
  std::printf("tuned / defaults: CPU %.3f, minor faults %.3f  (%s, %d steps from %s)\n",
              tuned.cpu_s / plain.cpu_s, double(tuned.minor_faults) / double(plain.minor_faults),
              file.c_str(), steps, checkpoint.empty() ? "t = 0" : checkpoint.c_str());
}
