#include "heap_tuning.hpp"

#include <cstdlib>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace fsi::app {

void keep_large_blocks_in_heap() {
#if defined(__GLIBC__)
  if (std::getenv("MALLOC_MMAP_MAX_") == nullptr) mallopt(M_MMAP_MAX, 0);
  // The largest trim threshold mallopt takes is INT_MAX; far above any run's heap peak.
  if (std::getenv("MALLOC_TRIM_THRESHOLD_") == nullptr) mallopt(M_TRIM_THRESHOLD, 0x7fffffff);
#endif
}

}  // namespace fsi::app
