// Sub-pixel sample positions (SPEC §4): the pixel centre for one sample, else
// Kensler's correlated multi-jittered samples ("Correlated Multi-Jittered
// Sampling", Pixar 2013). Each sample is a pure function of (pixel, index, count),
// so passes, tiles and threads can compute any sample in any order and still
// agree bit for bit.
#pragma once

#include <cstdint>

#include <libdivide.h>

namespace whitted {

struct SubPixel {
    double u, v;  // in [0,1)^2
};

// A divisor of the sample pattern, with what divides by it without a
// division instruction (libdivide) and the mask of the bits below its power
// of two.
struct SampleDivisor {
    std::uint32_t value = 1, bitMask = 0;
    libdivide::libdivide_u32_t by{};
};

// Kensler's pattern of `count` samples: count = columns * rows or a little
// less, the strata of the pixel. Made once a render (PreparedScene::pattern).
struct SamplePattern {
    SampleDivisor count, columns, rows;
};

SamplePattern samplePattern(int count);

// The per-pixel seed: a hash of the pixel's coordinates.
std::uint32_t pixelSeed(int i, int j);

// Sample `s` of `count` (0 <= s < count) for the pixel with seed `seed`.
SubPixel subPixelSample(int s, int count, std::uint32_t seed);

// Sample `s` of an open-ended sequence for the pixel with seed `seed`: the
// first two dimensions of Sobol's sequence, Owen-scrambled per pixel (Burley,
// "Practical Hash-based Owen Scrambling", JCGT 2020). Its first 2^k samples
// are stratified for every k: one in each of the 2^k cells of every grid of
// 2^a x 2^b cells with a + b = k. Renders that stop each tile at a count of
// their own (RenderOptions::adaptive) use it, so that whatever power of two a
// tile stops at, its samples are as well spread as a pattern made for that
// count; subPixelSample() is spread well only as a whole.
SubPixel progressiveSample(int s, std::uint32_t seed);

}  // namespace whitted
