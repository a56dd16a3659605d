#include "image/heat_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "image/image_compare.h"
#include "image/srgb.h"

namespace whitted {

namespace {

// Matplotlib's inferno (CC0) at entries 0, 32, 64, 96, 128, 160, 191, 223 and 255 of
// its 256, sRGB-encoded; the first stop is pure black instead of (0.001, 0.000, 0.014).
constexpr std::array<glm::vec3, 9> kInferno{{
    {0.000000f, 0.000000f, 0.000000f},
    {0.129285f, 0.047293f, 0.290788f},
    {0.341500f, 0.062325f, 0.429425f},
    {0.540920f, 0.134729f, 0.415123f},
    {0.735683f, 0.215906f, 0.330245f},
    {0.894305f, 0.353399f, 0.193584f},
    {0.977092f, 0.550850f, 0.039050f},
    {0.976108f, 0.789974f, 0.196018f},
    {0.988362f, 0.998364f, 0.644924f},
}};

}  // namespace

glm::vec3 heatMapColour(float difference) {
    if (!(difference > 0.0f)) return kInferno[0];
    const float x = std::min(difference / kHeatMapSaturation, 1.0f) * (kInferno.size() - 1);
    const int i = std::min(static_cast<int>(x), static_cast<int>(kInferno.size()) - 2);
    const float f = x - static_cast<float>(i);
    return kInferno[i] + f * (kInferno[i + 1] - kInferno[i]);
}

Image heatMap(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument("heatMap: the images differ in size");
    Image out(a.width, a.height);
    const std::size_t pixels = std::size_t(a.width) * std::size_t(a.height);
    for (std::size_t p = 0; p < pixels; ++p) {
        const glm::vec3 c = heatMapColour(displayDifference(&a.rgb[3 * p], &b.rgb[3 * p]));
        for (int k = 0; k < 3; ++k) out.rgb[3 * p + k] = srgbDecode(c[k]);
    }
    return out;
}

Image countMap(const std::vector<std::uint8_t>& counts, int width, int height, int top) {
    if (counts.size() != std::size_t(width) * std::size_t(height))
        throw std::invalid_argument("countMap: not one count a pixel");
    Image out(width, height);
    for (std::size_t p = 0; p < counts.size(); ++p) {
        const float share = top > 0 ? std::min(1.0f, float(counts[p]) / float(top)) : 0.0f;
        const glm::vec3 c = heatMapColour(share * kHeatMapSaturation);
        for (int k = 0; k < 3; ++k) out.rgb[3 * p + k] = srgbDecode(c[k]);
    }
    return out;
}

}  // namespace whitted
