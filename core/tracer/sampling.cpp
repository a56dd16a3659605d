#include "tracer/sampling.h"

#include <algorithm>
#include <cmath>

#include "tracer/sample_lanes.h"

namespace whitted {
namespace {

SampleDivisor divisor(std::uint32_t value) {
    SampleDivisor d;
    d.value = value;
    std::uint32_t w = value - 1;
    w |= w >> 1;
    w |= w >> 2;
    w |= w >> 4;
    w |= w >> 8;
    w |= w >> 16;
    d.bitMask = w;
    d.by = libdivide::libdivide_u32_gen(value);
    return d;
}

}  // namespace

SamplePattern samplePattern(int count) {
    // An m x n grid of strata with m*n >= count, each sample also alone in its
    // 1/count row: stratified in 2D and in each axis.
    const auto N = static_cast<std::uint32_t>(std::max(count, 1));
    const auto m = static_cast<std::uint32_t>(std::sqrt(static_cast<double>(N)));
    const std::uint32_t n = (N + m - 1) / m;
    return {divisor(N), divisor(m), divisor(n)};
}

SubPixel progressiveSample(int s, std::uint32_t seed) {
    const OffsetLanes<std::uint32_t> offset = sequenceOffsets(std::uint32_t(s), seed);
    return {offset.u[0], offset.v[0]};
}

std::uint32_t pixelSeed(int i, int j) {
    return pixelSeeds(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j));
}

SubPixel subPixelSample(int s, int count, std::uint32_t seed) {
    if (count <= 1) return {0.5, 0.5};
    const OffsetLanes<std::uint32_t> offset =
        patternOffsets(std::uint32_t(s), samplePattern(count), seed);
    return {offset.u[0], offset.v[0]};
}

}  // namespace whitted
