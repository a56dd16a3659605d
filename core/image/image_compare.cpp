#include "image/image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "image/srgb.h"

namespace whitted {

float displayDifference(const float* a, const float* b) {
    float largest = 0.0f;
    for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(a[c]) || !std::isfinite(b[c])) return 1.0f;
        largest = std::max(largest, std::fabs(srgbEncode(a[c]) - srgbEncode(b[c])));
    }
    return largest;
}

float displayDifferenceAtMost(const float* a, const float* b) {
    int largestCodes = 0;
    for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(a[c]) || !std::isfinite(b[c])) return 1.0f;
        largestCodes =
            std::max(largestCodes, std::abs(int(srgbEncode8(a[c])) - int(srgbEncode8(b[c]))));
    }
    return (float(largestCodes) + kCodeRoundingSlack) / 255.0f;
}

ImageDifference compareImages(const Image& a, const Image& b, float threshold) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument("compareImages: the images differ in size");
    ImageDifference d;
    d.pixels = std::size_t(a.width) * std::size_t(a.height);
    for (std::size_t i = 0; i < d.pixels; ++i) {
        const float diff = displayDifference(&a.rgb[3 * i], &b.rgb[3 * i]);
        d.largest = std::max(d.largest, diff);
        if (diff > threshold) ++d.over;
    }
    return d;
}

}  // namespace whitted
