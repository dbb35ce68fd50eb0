// fsi-movie and fsi-step keep large blocks in the heap (apps/common/heap_tuning.hpp): a
// factorization-sized block must not come from a fresh mmap, and freeing it must leave
// its pages for the next one.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

#include "heap_tuning.hpp"
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace {

#if defined(__GLIBC__)
TEST(HeapTuning, FactorizationSizedBlocksStayInTheHeap) {
  if (std::getenv("MALLOC_MMAP_MAX_") || std::getenv("MALLOC_TRIM_THRESHOLD_"))
    GTEST_SKIP() << "the environment sets glibc's malloc tuning; the app leaves it alone";
  fsi::app::keep_large_blocks_in_heap();
  const std::size_t bytes = 64u << 20;  // above glibc's largest mmap threshold (32 MB)
  for (int round = 0; round < 2; ++round) {
    void* volatile block = std::malloc(bytes);
    ASSERT_NE(block, nullptr);
    std::memset(block, 1, bytes);
    EXPECT_EQ(mallinfo2().hblks, 0u) << "round " << round << ": the block was mmapped";
    std::free(block);
    // Not trimmed: the freed pages stay in the heap for the next factorization.
    EXPECT_GE(mallinfo2().fordblks, bytes) << "round " << round;
  }
}
#endif

}  // namespace
