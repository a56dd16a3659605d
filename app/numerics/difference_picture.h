// The sweep's picture of where a render differs from its reference, written
// beside each failing point (docs/numerics.md): displayDifference() per pixel as
// a black-red-yellow-white ramp that saturates at `saturation`, with magenta
// for NaN and Inf. Not the editor's heat map (core/image/heat_map.h), whose
// inferno ramp has no colour for a non-finite pixel.
#pragma once

#include "image/image.h"

namespace whitted::numerics {

// The display difference at which the picture reaches white.
inline constexpr float kDifferenceWhite = 8.0f / 255.0f;

// A linear RGB image (for writeImage, whose 8-bit output then shows the ramp's
// exact codes): black where `image` equals `reference` in display values,
// brighter with the difference, white from `saturation` on; magenta where
// `image` has a NaN or infinite channel. The images must have the same size.
Image differencePicture(const Image& image, const Image& reference,
                        float saturation = kDifferenceWhite);

}  // namespace whitted::numerics
