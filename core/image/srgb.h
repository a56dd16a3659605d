// The sRGB transfer curve, shared by 8-bit export and the editor's view so that
// both show the same pixels (SPEC §5).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace whitted {

// Linear value to sRGB-encoded value, both in [0,1]; the input is clamped first
// (NaN becomes 0).
float srgbEncode(float linear);

// srgbEncode() from a table, interpolated within 1/128 of an octave: within
// 1e-5 of the formula (a four-hundredth of an 8-bit code), at a tenth of
// std::pow's cost. For estimates taken per pixel and pass (adaptive_sampling.h).
float srgbEncodeFast(float linear);
// The same for `count` values at once, into `encoded`.
void srgbEncodeFast(const float* linear, std::size_t count, float* encoded);

// Linear value to an 8-bit sRGB code, clamped and rounded to nearest.
std::uint8_t srgbEncode8(float linear);
// The same for `count` values at once, into `codes`.
void srgbEncode8(const float* linear, std::size_t count, std::uint8_t* codes);

// sRGB-encoded value in [0,1] back to linear: in float for pixels, in double
// for a value the user picks (the colour dialog's).
template <typename T>
T srgbDecode(T encoded) {
    return encoded <= T(0.04045) ? encoded / T(12.92)
                                 : std::pow((encoded + T(0.055)) / T(1.055), T(2.4));
}

// 8-bit sRGB code back to linear.
float srgbDecode8(std::uint8_t code);

}  // namespace whitted
