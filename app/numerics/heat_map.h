// A picture of where two renders differ: displayDifference() per pixel as a
// black-red-yellow-white ramp that saturates at `saturation`.
#pragma once

#include "image.h"

namespace whitted::numerics {

// The display difference at which the heat map reaches white.
inline constexpr float kHeatSaturation = 8.0f / 255.0f;

// A linear RGB image (for writeImage, whose 8-bit output then shows the ramp's
// exact codes): black where `image` equals `reference` in display values,
// brighter with the difference, white from `saturation` on; magenta where
// `image` has a NaN or infinite channel. The images must have the same size.
Image heatMap(const Image& image, const Image& reference, float saturation = kHeatSaturation);

}  // namespace whitted::numerics
