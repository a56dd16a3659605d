// Large buffers (images, sample sums, the BVH) come zeroed whether their pages
// are fresh from mmap or kept from an earlier buffer of the same size; a kept
// buffer is handed out once only. Ordinary large blocks, in the editor, come
// back from the heap without new pages.
#include <sys/resource.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "base/heap_reuse.h"
#include "base/large_buffer_allocator.h"
#include "support/test_support.h"

namespace whitted {
namespace {

using Floats = std::vector<float, LargeBufferAllocator<float>>;
constexpr std::size_t kPixels = 1280 * 720 * 3;  // a 1280x720 image, 11 MB

TEST(LargeBuffer, AReusedBufferComesBackZeroed) {
    const float* first = nullptr;
    {
        Floats image(kPixels);
        for (std::size_t i = 0; i < image.size(); i += 1000) image[i] = 1.0f + float(i);
        image.back() = 7.0f;
        first = image.data();
    }
    Floats again(kPixels);
    EXPECT_EQ(again.data(), first) << "the freed buffer of the same size was not reused";
    for (std::size_t i = 0; i < again.size(); ++i) ASSERT_EQ(again[i], 0.0f) << "element " << i;
}

TEST(LargeBuffer, TwoLiveBuffersNeverShareMemory) {
    { Floats warm(kPixels); }
    Floats a(kPixels), b(kPixels);
    EXPECT_NE(a.data(), b.data());
    a.assign(a.size(), 1.0f);
    for (std::size_t i = 0; i < b.size(); i += 997) ASSERT_EQ(b[i], 0.0f) << "element " << i;
}

// Alignment beyond new's 16 bytes (the BVH build's 32-byte lanes) holds on
// both the small-buffer path and the page path.
TEST(LargeBuffer, OverAlignedElementsAreAligned) {
    struct alignas(32) Lanes {
        double v[4];
    };
    for (std::size_t n : {std::size_t(3), std::size_t(1) << 16}) {
        std::vector<Lanes, LargeBufferAllocator<Lanes>> lanes(n);
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(lanes.data()) % 32, 0u) << n << " elements";
    }
}

long minorFaults() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_minflt;
}

// What an edit of a million spheres does twice over in the editor: a block as
// large as their list (glibc would map it afresh) filled, freed, and a block of
// the same size filled again. The second must find its pages present.
TEST(HeapReuse, ABlockFreedComesBackWithItsPages) {
    if (test::kSanitized) GTEST_SKIP() << "the sanitizers' allocators ignore mallopt";
    reuseHeapForLargeBlocks();
    constexpr std::size_t kBytes = std::size_t(96) << 20;
    constexpr long kPages = long(kBytes >> 12);
    auto filled = [&] {
        std::vector<char> block(kBytes);
        std::memset(block.data(), 1, block.size());
        return block[kBytes / 2];
    };
    EXPECT_EQ(filled(), 1);
    const long before = minorFaults();
    EXPECT_EQ(filled(), 1);
    EXPECT_LT(minorFaults() - before, kPages / 100)
        << "the second block took new pages: it was mapped afresh, not reused";
}

}  // namespace
}  // namespace whitted
