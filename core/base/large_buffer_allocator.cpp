// The pages behind LargeBufferAllocator: mmap, with the last few freed
// buffers kept for a request of the same size (why: large_buffer_allocator.h).
#include "base/large_buffer_allocator.h"

#include <sys/mman.h>

#include <cstring>
#include <deque>
#include <mutex>
#include <new>

namespace whitted {
namespace {

// Enough for the editor's image and sample sums of two renders in flight (the
// one on screen and the next), and a bound on memory held for nothing.
constexpr std::size_t kKeptBuffers = 4;
constexpr std::size_t kKeptBytes = std::size_t(256) << 20;

struct Buffer {
    void* pages;
    std::size_t bytes;
};

struct KeptBuffers {
    std::mutex mutex;
    std::deque<Buffer> buffers;  // oldest first
    std::size_t bytes = 0;
};

// Never destroyed: a static buffer may be freed after this would have been.
KeptBuffers& kept() {
    static KeptBuffers* k = new KeptBuffers;
    return *k;
}

void* takeKept(std::size_t bytes) {
    KeptBuffers& k = kept();
    std::lock_guard lock(k.mutex);
    for (auto it = k.buffers.rbegin(); it != k.buffers.rend(); ++it) {
        if (it->bytes != bytes) continue;
        void* pages = it->pages;
        k.buffers.erase(std::next(it).base());
        k.bytes -= bytes;
        return pages;
    }
    return nullptr;
}

}  // namespace

void* allocateZeroedPages(std::size_t bytes) {
    if (void* pages = takeKept(bytes)) return std::memset(pages, 0, bytes);
    void* pages =
        ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (pages == MAP_FAILED) throw std::bad_alloc();
    return pages;
}

void releasePages(void* pages, std::size_t bytes) {
    std::deque<Buffer> evicted;
    if (bytes <= kKeptBytes) {
        KeptBuffers& k = kept();
        std::lock_guard lock(k.mutex);
        k.buffers.push_back({pages, bytes});
        k.bytes += bytes;
        while (k.buffers.size() > kKeptBuffers || k.bytes > kKeptBytes) {
            evicted.push_back(k.buffers.front());
            k.bytes -= k.buffers.front().bytes;
            k.buffers.pop_front();
        }
    } else {
        evicted.push_back({pages, bytes});
    }
    for (const Buffer& b : evicted) ::munmap(b.pages, b.bytes);
}

}  // namespace whitted
