// The float-versus-double view's picture of where two renders differ: per pixel,
// displayDifference() (image_compare.h, the metric the numerics tests and the
// sweep count with) as a colour.
//
// The ramp is matplotlib's "inferno" (perceptually uniform, lightness rising
// monotonically, readable without colour vision), its first stop moved to pure
// black so that identical pixels are black and any difference shows. It is
// linear in the difference and saturates at kHeatMapSaturation: 1/255 is dark
// purple, 4/255 orange-red, 8/255 and more pale yellow.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "image/image.h"

namespace whitted {

// A difference of 8 steps of the 8-bit display is the top of the ramp.
inline constexpr float kHeatMapSaturation = 8.0f / 255.0f;

// The display colour (sRGB-encoded, each channel in [0, 1]) for a displayDifference().
glm::vec3 heatMapColour(float difference);

// The heat map of two images of the same size (std::invalid_argument otherwise),
// as a linear image: shown through the sRGB curve (SPEC §5), as the editor and
// PNG export do, each pixel is heatMapColour() to within half an 8-bit step.
Image heatMap(const Image& a, const Image& b);

// A map of small counts on the same ramp, 0 black and `top` (or more) pale
// yellow: how deep Whitted's 1980 sampling cut each pixel. `counts` holds
// width x height values, row by row; a linear image as heatMap()'s.
Image countMap(const std::vector<std::uint8_t>& counts, int width, int height, int top);

}  // namespace whitted
