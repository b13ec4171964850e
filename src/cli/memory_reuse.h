// The process's allocator told to keep and reuse what it frees, set once at start-up, and its
// heap backed by huge pages when a run is about to fill tens of megabytes of it.
#pragma once

namespace curdle::cli {

// By default glibc hands every block over 128 KB back to the system when it is freed, so each
// output's buffers, grown and freed in turn, are mapped and zeroed page by page again: a fifth
// of a perforated screen's whole run went to those page faults. Blocks up to 32 MB now come
// from the heap, and up to 256 MB of freed memory stays there for the next output.
void keep_freed_memory_for_reuse();

// The heap grown by 64 MB at once and advised to be backed by 2 MB pages (THP "madvise",
// Debian's default), for a run that lays a layout (app::builds_layout): its writers fill 50 MB of
// heap, and on a machine that pays 30 µs a page fault its 4 KB pages were a tenth of a
// perforated screen's run. glibc does as much with GLIBC_TUNABLES=glibc.malloc.hugetlb=1,
// which only the environment can set. Not for every run: a curd alone touches little heap,
// and zeroing whole 2 MB pages made it slower.
void back_the_heap_with_huge_pages();

}  // namespace curdle::cli
