// An allocator for arrays whose every element is written before it is read,
// by several threads each into its own part (SphereSet, filled by
// prepareScene): resizing them writes nothing, so no thread zeroes a million
// spheres' arrays first, and fresh pages are first touched by the threads that
// fill them. Plain operator new otherwise: freed arrays go back to the heap
// rather than into LargeBufferAllocator's few kept buffers, which hold the
// editor's image buffers.
#pragma once

#include <memory>
#include <new>
#include <utility>

namespace whitted {

template <typename T>
struct UninitialisedAllocator : std::allocator<T> {
    using value_type = T;
    template <typename U>
    struct rebind {
        using other = UninitialisedAllocator<U>;
    };

    UninitialisedAllocator() = default;
    template <typename U>
    UninitialisedAllocator(const UninitialisedAllocator<U>&) {}

    // Value-initialisation leaves the element as default-initialisation does
    // (for plain numbers: unwritten); every other construction is the ordinary one.
    template <typename U>
    void construct(U* p) noexcept {
        ::new (static_cast<void*>(p)) U;
    }
    template <typename U, typename... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

}  // namespace whitted
