#pragma once
/// \file heap_tuning.hpp
/// Long runs factorize a large sparse matrix at almost every step; UMFPACK allocates a
/// fresh numeric object each time (125 MB for the stairs). glibc serves blocks that large
/// with a new mmap and returns them to the kernel on free, so every factorization
/// page-faults its whole workspace in again: 9-10 % of a stairs step was the kernel's
/// page-fault handling (perf, on the stairs). Keeping large blocks in the heap lets the
/// next factorization reuse the same pages (12 % less CPU over six stairs steps, 94 % fewer
/// page faults, identical results: bench/heap_bench.cpp).
namespace fsi::app {

/// Asks glibc to serve every block from the heap and never to trim it, unless the user
/// set MALLOC_MMAP_MAX_ or MALLOC_TRIM_THRESHOLD_ (their choice wins). Costs resident
/// memory equal to the run's peak, which the run reaches anyway. No effect off glibc.
void keep_large_blocks_in_heap();

}  // namespace fsi::app
