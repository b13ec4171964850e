#include "cli/memory_reuse.h"

#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>

namespace curdle::cli {

void keep_freed_memory_for_reuse() {
  // Each call only tunes the allocator; a libc without these options ignores them.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);  // glibc's largest: half its 64 MB heap
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
}

void back_the_heap_with_huge_pages() {
  constexpr int kGrowth = 64 << 20;
  constexpr uintptr_t kHugePage = uintptr_t{2} << 20;
  const auto begin = reinterpret_cast<uintptr_t>(sbrk(0));
  mallopt(M_TOP_PAD, kGrowth);
  // More than the heap has left, so that it grows by the pad (volatile: a compiler may drop a
  // block freed unused).
  void* volatile block = malloc(256 << 10);
  free(block);
  mallopt(M_TOP_PAD, 128 << 10);  // glibc's default for any growth after
  const auto end = reinterpret_cast<uintptr_t>(sbrk(0));
  const uintptr_t from = (begin + kHugePage - 1) & ~(kHugePage - 1);
  // Only threads that share the main heap gain; a kernel without THP refuses, harmlessly.
  if (end > from + kHugePage) madvise(reinterpret_cast<void*>(from), end - from, MADV_HUGEPAGE);
}

}  // namespace curdle::cli
