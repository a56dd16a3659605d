#include "base/heap_reuse.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace whitted {

void reuseHeapForLargeBlocks() {
#if defined(__GLIBC__)
    // No block from mmap, and free memory at the heap's top kept up to this
    // much, rather than given back and faulted in again by the next copy.
    constexpr int kKeptTopBytes = 512 << 20;
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, kKeptTopBytes);
#endif
}

}  // namespace whitted
