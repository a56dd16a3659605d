// Large buffers (images, sample sums, the BVH) come zeroed whether their pages
// are fresh from mmap or kept from an earlier buffer of the same size; a kept
// buffer is handed out once only.
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "base/large_buffer_allocator.h"

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

}  // namespace
}  // namespace whitted
