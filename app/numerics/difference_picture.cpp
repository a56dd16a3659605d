#include "difference_picture.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "image/image_compare.h"
#include "image/srgb.h"

namespace whitted::numerics {

namespace {

using Code = std::array<std::uint8_t, 3>;

// Black to red to yellow to white in equal thirds: brightness rises throughout,
// so the map reads in grey too.
Code ramp(float t) {
    const float x = std::clamp(t, 0.0f, 1.0f) * 3.0f;
    auto code = [](float v) { return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255)); };
    return {code(x), code(x - 1.0f), code(x - 2.0f)};
}

bool finite(const float* p) {
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

}  // namespace

Image differencePicture(const Image& image, const Image& reference, float saturation) {
    if (image.width != reference.width || image.height != reference.height)
        throw std::invalid_argument("heatMap: the images differ in size");
    constexpr Code kNonFinite{255, 0, 255};
    Image out(image.width, image.height);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float* p = image.pixel(x, y);
            const Code c = finite(p)
                               ? ramp(displayDifference(p, reference.pixel(x, y)) / saturation)
                               : kNonFinite;
            float* o = out.pixel(x, y);
            for (int ch = 0; ch < 3; ++ch) o[ch] = srgbDecode8(c[ch]);
        }
    return out;
}

}  // namespace whitted::numerics
