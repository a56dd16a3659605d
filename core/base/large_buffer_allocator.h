// An allocator for pixel buffers whose zeroing costs nothing up front.
//
// Why: a 1280x720 RGB float image is 11 MB, 2,700 pages of 4 KiB. Zeroing it
// in the constructor took 5.5 ms of a 28 ms render on this project's virtual
// machines, nearly all in page faults, on one thread before rendering began.
// Large buffers come straight from mmap, which hands out zeroed pages, and
// value-initialising an element writes nothing; each page is then touched
// first by the worker thread that renders into it, in parallel with the others.
// (Also tried: transparent huge pages, whose compaction made some allocations
// take 10 to 50 ms; MAP_POPULATE, which still cost 5 ms on one thread.)
//
// Fresh pages cost a fault each on first touch, and on these virtual machines
// the 2,700 faults of a 1280x720 image took most of the editor's coarse
// preview, every edit. So a few freed buffers are kept, and a request of the
// same size gets one back, zeroed by memset: a millisecond instead of tens.
#pragma once

#include <cstddef>
#include <cstring>
#include <new>

#include "base/uninitialised_allocator.h"

namespace whitted {

// Zeroed memory from mmap, or from the buffers freed last (large_buffer_allocator.cpp).
void* allocateZeroedPages(std::size_t bytes);
void releasePages(void* pages, std::size_t bytes);

// Value-initialisation leaves the (already zero) memory alone; every other
// construction, copies and fills included, is the ordinary one
// (UninitialisedAllocator's construct()).
template <typename T>
struct LargeBufferAllocator : UninitialisedAllocator<T> {
    using value_type = T;
    template <typename U>
    struct rebind {
        using other = LargeBufferAllocator<U>;
    };
    static constexpr std::size_t kLarge = std::size_t(1) << 20;
    // Vector lanes (bvh_split.h) need more than new's 16 bytes, and a tree's
    // sibling nodes share a line only if the array starts on one (bvh.h):
    // cache-line aligned at least. mmap gives pages.
    static constexpr std::align_val_t kAlign{alignof(T) > 64 ? alignof(T) : 64};

    LargeBufferAllocator() = default;
    template <typename U>
    LargeBufferAllocator(const LargeBufferAllocator<U>&) {}

    T* allocate(std::size_t n) {
        const std::size_t bytes = n * sizeof(T);
        if (bytes < kLarge)
            return static_cast<T*>(std::memset(::operator new(bytes, kAlign), 0, bytes));
        return static_cast<T*>(allocateZeroedPages(bytes));
    }

    void deallocate(T* p, std::size_t n) {
        if (n * sizeof(T) < kLarge)
            ::operator delete(p, kAlign);
        else
            releasePages(p, n * sizeof(T));
    }

    template <typename U>
    bool operator==(const LargeBufferAllocator<U>&) const {
        return true;
    }
};

}  // namespace whitted
