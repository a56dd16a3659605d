// The renderer's image: linear RGB floats, row-major, top row first (SPEC §5).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "base/large_buffer_allocator.h"

namespace whitted {

// A rectangle of pixels: columns [x, x + width), rows [y, y + height).
struct PixelRect {
    int x, y, width, height;
};

// Whether the rectangle holds a pixel and lies within a width x height picture.
inline bool insidePicture(const PixelRect& r, int width, int height) {
    return r.width > 0 && r.height > 0 && r.x >= 0 && r.y >= 0 && r.x + r.width <= width &&
           r.y + r.height <= height;
}

// Whether the rectangle holds pixel (x, y).
inline bool contains(const PixelRect& r, int x, int y) {
    return x >= r.x && x < r.x + r.width && y >= r.y && y < r.y + r.height;
}

// Whether the two rectangles share a pixel.
inline bool overlap(const PixelRect& a, const PixelRect& b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height &&
           b.y < a.y + a.height;
}

// "X0,Y0,X1,Y1", as whitted-render's --region takes it.
inline std::string cornersText(const PixelRect& r) {
    return std::to_string(r.x) + "," + std::to_string(r.y) + "," + std::to_string(r.x + r.width) +
           "," + std::to_string(r.y + r.height);
}

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
