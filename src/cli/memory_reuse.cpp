#include "cli/memory_reuse.h"

#include <malloc.h>

namespace curdle::cli {

void keep_freed_memory_for_reuse() {
  // Each call only tunes the allocator; a libc without these options ignores them.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);  // glibc's largest: half its 64 MB heap
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
}

}  // namespace curdle::cli
