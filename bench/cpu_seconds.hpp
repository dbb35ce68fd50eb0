#pragma once
// CPU seconds (user + sys) of this process: the benchmarks compare CPU, not wall time,
// since the machines are shared.
#include <sys/resource.h>

namespace fsi::bench {

inline double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  const auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
  return seconds(u.ru_utime) + seconds(u.ru_stime);
}

}  // namespace fsi::bench
