// The renderer's image: linear RGB floats, row-major, top row first (SPEC §5).
#pragma once

#include <cstddef>
#include <vector>

#include "large_buffer_allocator.h"

namespace whitted {

// A rectangle of pixels: columns [x, x + width), rows [y, y + height).
struct PixelRect {
    int x, y, width, height;
};

struct Image {
    int width = 0;
    int height = 0;
    // width * height * 3, pixel (x, y) at 3 * (y * width + x)
    std::vector<float, LargeBufferAllocator<float>> rgb;

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgb(std::size_t(w) * std::size_t(h) * 3) {}  // zero
    float* pixel(int x, int y) { return &rgb[3 * (std::size_t(y) * width + x)]; }
    const float* pixel(int x, int y) const { return &rgb[3 * (std::size_t(y) * width + x)]; }
    bool operator==(const Image&) const = default;
};

}  // namespace whitted
