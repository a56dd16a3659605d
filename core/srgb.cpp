#include "srgb.h"

#include <cmath>

namespace whitted {

float srgbEncode(float linear) {
    if (!(linear > 0.0f)) return 0.0f;
    if (linear >= 1.0f) return 1.0f;
    if (linear <= 0.0031308f) return 12.92f * linear;
    return 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

std::uint8_t srgbEncode8(float linear) {
    return static_cast<std::uint8_t>(std::lround(srgbEncode(linear) * 255.0f));
}

float srgbDecode8(std::uint8_t code) {
    const float c = code / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

}  // namespace whitted
