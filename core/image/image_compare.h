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

// Each 8-bit code is its encoded value rounded, so two encoded values differ
// by less than one code more than their codes do; the rest is float
// arithmetic's.
inline constexpr float kCodeRoundingSlack = 1.01f;

// At least displayDifference(a, b), from the pixels' 8-bit codes: no
// std::pow, for a search that needs the exact difference only where it may
// be over a limit or a largest so far.
float displayDifferenceAtMost(const float* a, const float* b);

struct ImageDifference {
    std::size_t pixels = 0;  // pixels compared
    std::size_t over = 0;    // pixels whose displayDifference() exceeds the threshold
    float largest = 0.0f;    // the largest displayDifference()
    double fractionOver() const { return pixels ? double(over) / double(pixels) : 0.0; }
};

// The images must have the same size (std::invalid_argument otherwise).
ImageDifference compareImages(const Image& a, const Image& b, float threshold);

}  // namespace whitted
