// The process's allocator told to keep and reuse what it frees, set once at start-up.
#pragma once

namespace curdle::cli {

// By default glibc hands every block over 128 KB back to the system when it is freed, so each
// output's buffers, grown and freed in turn, are mapped and zeroed page by page again: a fifth
// of a perforated screen's whole run went to those page faults. Blocks up to 32 MB now come
// from the heap, and up to 256 MB of freed memory stays there for the next output.
void keep_freed_memory_for_reuse();

}  // namespace curdle::cli
