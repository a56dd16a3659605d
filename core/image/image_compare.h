// How far apart two renders of one scene are, in what a person sees: the
// sRGB-encoded display values of SPEC §5, per pixel the largest channel
// difference. Shared by the numerics tests, the sweep program and the
// editor's float-versus-double view, so all three count the same pixels.
#pragma once

#include <cstddef>

#include "image/image.h"

namespace whitted {

// Largest channel difference of two linear RGB pixels after the sRGB curve,
// in [0, 1]. A NaN or infinite channel on either side counts as 1.
float displayDifference(const float* a, const float* b);

struct ImageDifference {
    std::size_t pixels = 0;  // pixels compared
    std::size_t over = 0;    // pixels whose displayDifference() exceeds the threshold
    float largest = 0.0f;    // the largest displayDifference()
    double fractionOver() const { return pixels ? double(over) / double(pixels) : 0.0; }
};

// The images must have the same size (std::invalid_argument otherwise).
ImageDifference compareImages(const Image& a, const Image& b, float threshold);

}  // namespace whitted
