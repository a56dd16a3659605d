// Sub-pixel sample positions (SPEC §4): the pixel centre for one sample, else
// Kensler's correlated multi-jittered samples ("Correlated Multi-Jittered
// Sampling", Pixar 2013). Each sample is a pure function of (pixel, index, count),
// so passes, tiles and threads can compute any sample in any order and still
// agree bit for bit.
#pragma once

#include <cstdint>

namespace whitted {

struct SubPixel {
    double u, v;  // in [0,1)^2
};

// The per-pixel seed: a hash of the pixel's coordinates.
std::uint32_t pixelSeed(int i, int j);

// Sample `s` of `count` (0 <= s < count) for the pixel with seed `seed`.
SubPixel subPixelSample(int s, int count, std::uint32_t seed);

}  // namespace whitted
