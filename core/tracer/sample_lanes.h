// The sub-pixel samples of sampling.h, for one pixel or a packet's pixels at
// once. Each hash is written once for a lane type U: std::uint32_t (one pixel)
// or a GCC vector of them (a camera packet's, kernelCameraRows()). A lane's
// values are the same whatever U is, bit for bit; a vector only computes
// several at once.
// Made one pixel at a time, with a hardware division in each of Kensler's
// permutations, the positions took nearly a third of the CPU time of renders
// of 8 and 32 samples a pixel (bench_editor_prediction; docs/design/performance.md).
#pragma once

#include <cstdint>
#include <type_traits>

#include "tracer/isa_namespace.h"
#include "tracer/sampling.h"
#include "tracer/simd.h"

namespace whitted {

inline namespace WHITTED_ISA_NAMESPACE {

// Lanes of 32-bit words, as many as a packet of T has lanes. The attribute
// cannot take a template parameter, hence the two specialisations.
template <typename T>
struct LaneWords;
template <>
struct LaneWords<float> {
    typedef std::uint32_t type __attribute__((vector_size(kSimdBytes)));
};
template <>
struct LaneWords<double> {
    typedef std::uint32_t type __attribute__((vector_size(kSimdBytes / 2)));
};

template <typename U>
inline constexpr int kLaneCount = int(sizeof(U) / sizeof(std::uint32_t));

template <typename U>
inline std::uint32_t laneOf(const U& words, int lane) {
    if constexpr (std::is_integral_v<U>)
        return words;
    else
        return words[lane];
}

template <typename U>
inline U lanesOf(std::uint32_t word) {
    if constexpr (std::is_integral_v<U>)
        return word;
    else
        return U{} + word;
}

template <typename M>
inline bool anyLane(const M& mask) {
    if constexpr (std::is_same_v<M, bool>) {
        return mask;
    } else {
        bool any = false;
        for (int l = 0; l < kLaneCount<M>; ++l) any |= mask[l] != 0;
        return any;
    }
}

// x % divisor, through libdivide's multiply and shift: the one thing here
// that a vector has no instruction for, so it is done lane by lane.
template <typename U>
inline U remainderOf(U x, const SampleDivisor& divisor) {
    auto remainder = [&](std::uint32_t word) {
        return word - libdivide::libdivide_u32_do(word, &divisor.by) * divisor.value;
    };
    if constexpr (std::is_integral_v<U>) {
        return remainder(x);
    } else {
        for (int l = 0; l < kLaneCount<U>; ++l) x[l] = remainder(x[l]);
        return x;
    }
}

template <typename U>
inline U quotientOf(U x, const SampleDivisor& divisor) {
    if constexpr (std::is_integral_v<U>) {
        return libdivide::libdivide_u32_do(x, &divisor.by);
    } else {
        for (int l = 0; l < kLaneCount<U>; ++l)
            x[l] = libdivide::libdivide_u32_do(x[l], &divisor.by);
        return x;
    }
}

// One round of Kensler's permutation hash (listing 2); `w` masks the bits of
// the permuted range.
template <typename U>
inline U permuteRound(U i, const U& p, std::uint32_t w) {
    i ^= p;
    i *= 0xe170893du;
    i ^= p >> 16;
    i ^= (i & w) >> 4;
    i ^= p >> 8;
    i *= 0x0929eb3fu;
    i ^= p >> 23;
    i ^= (i & w) >> 1;
    i *= 1u | p >> 27;
    i *= 0x6935fa69u;
    i ^= (i & w) >> 11;
    i *= 0x74dcb303u;
    i ^= (i & w) >> 2;
    i *= 0x9e501cc3u;
    i ^= (i & w) >> 2;
    i *= 0xc860a3dfu;
    i &= w;
    i ^= i >> 5;
    return i;
}

// Kensler's permutation of [0, range) (listing 2): rounds until the value is
// in range (cycle walking), each lane stopping at its own round, then rotated by p.
template <typename U>
inline U permute(U i, const SampleDivisor& range, const U& p) {
    i = permuteRound(i, p, range.bitMask);
    auto pending = i >= range.value;
    while (anyLane(pending)) {
        const U next = permuteRound(i, p, range.bitMask);
        i = pending ? next : i;
        pending = pending && i >= range.value;
    }
    return remainderOf(U(i + p), range);
}

// Kensler's hashed value (listing 3), as 32 bits of a fraction.
template <typename U>
inline U randomBits(U i, const U& p) {
    i ^= p;
    i ^= i >> 17;
    i ^= i >> 10;
    i *= 0xb36534e5u;
    i ^= i >> 12;
    i ^= i >> 21;
    i *= 0x93fc4795u;
    i ^= 0xdf6e307fu;
    i ^= i >> 17;
    i *= 1u | p >> 18;
    return i;
}

template <typename U>
inline U reverseBits(U x) {
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    return ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
}

// Owen scrambling of a value in [0, 2^32) read as a binary fraction: each bit
// is flipped by a hash of the bits above it (Laine and Karras's permutation,
// applied to the reversed bits so that "above" becomes "below"). Takes the
// value's bits already reversed.
template <typename U>
inline U owenScrambleReversed(U reversed, const U& seed) {
    U x = reversed + seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return reverseBits(x);
}

template <typename U>
inline U hashSeed(U seed, std::uint32_t salt) {
    seed ^= salt;
    seed *= 0x9e3779b9u;
    seed ^= seed >> 16;
    seed *= 0x85ebca6bu;
    return seed ^ (seed >> 13);
}

// Sobol's second dimension: the bits of `index` select direction numbers
// v_0 = 1/2, v_k = v_{k-1} xor v_{k-1}/2 (the first dimension is the index
// with its bits reversed).
template <typename U>
inline U sobolSecond(U index) {
    std::uint32_t v = 0x80000000u;
    U x = lanesOf<U>(0);
    for (; anyLane(index != 0); index >>= 1, v ^= v >> 1) x ^= (index & 1u) * v;
    return x;
}

// PCG-style integer hash of the packed coordinates (both < 2^14 + 1); j is
// one row for all lanes or a row a lane.
template <typename U, typename J>
inline U pixelSeeds(const U& i, const J& j) {
    U x = (j << 15) ^ i;
    x = x * 747796405u + 2891336453u;
    const U word = ((x >> ((x >> 28u) + 4u)) ^ x) * 277803737u;
    return (word >> 22u) ^ word;
}

// Sub-pixel offsets in [0,1)^2, lane by lane.
template <typename U>
struct OffsetLanes {
    double u[kLaneCount<U>], v[kLaneCount<U>];
};

// Samples `indices` of Kensler's correlated multi-jittered pattern of
// pattern.count samples (subPixelSample()), for pixels of the given seeds.
template <typename U>
inline OffsetLanes<U> patternOffsets(const U& indices, const SamplePattern& pattern,
                                     const U& seeds) {
    const U si = permute(indices, pattern.count, U(seeds * 0x51633e2du));
    const U sx = permute(remainderOf(si, pattern.columns), pattern.columns, U(seeds * 0x68bc21ebu));
    const U sy = permute(quotientOf(si, pattern.columns), pattern.rows, U(seeds * 0x02e5be93u));
    const U jx = randomBits(si, U(seeds * 0x967a889bu));
    const U jy = randomBits(si, U(seeds * 0x368cc8b7u));
    constexpr double kUnit = 1.0 / 4294967296.0;
    const double m = pattern.columns.value, n = pattern.rows.value, count = pattern.count.value;
    OffsetLanes<U> out;
    for (int l = 0; l < kLaneCount<U>; ++l) {
        out.u[l] = (laneOf(sx, l) + (laneOf(sy, l) + laneOf(jx, l) * kUnit) / n) / m;
        out.v[l] = (laneOf(si, l) + laneOf(jy, l) * kUnit) / count;
    }
    return out;
}

// Samples `indices` of the Owen-scrambled Sobol sequence
// (progressiveSample()), for pixels of the given seeds.
template <typename U>
inline OffsetLanes<U> sequenceOffsets(const U& indices, const U& seeds) {
    const U x = owenScrambleReversed(indices, hashSeed(seeds, 0x2c1b3c6du));
    const U y =
        owenScrambleReversed(reverseBits(sobolSecond(indices)), hashSeed(seeds, 0x297a2d39u));
    // The top 24 bits: exact in float too, and below 1.
    constexpr double kUnit = 1.0 / 16777216.0;
    OffsetLanes<U> out;
    for (int l = 0; l < kLaneCount<U>; ++l) {
        out.u[l] = (laneOf(x, l) >> 8) * kUnit;
        out.v[l] = (laneOf(y, l) >> 8) * kUnit;
    }
    return out;
}

// Sample `n` (or each lane's of `indices`) of the pixels of the given seeds,
// as a render draws it: from the open-ended sequence (renders whose tiles
// stop at counts of their own) or from the pattern of pattern.count samples.
// The packet's and the single pixel's paths both ask here, so they cannot
// choose differently.
template <typename U>
inline OffsetLanes<U> sampleOffsets(const U& indices, bool openEnded, const SamplePattern& pattern,
                                    const U& seeds) {
    return openEnded ? sequenceOffsets(indices, seeds) : patternOffsets(indices, pattern, seeds);
}

template <typename U>
inline OffsetLanes<U> sampleOffsets(int n, bool openEnded, const SamplePattern& pattern,
                                    const U& seeds) {
    return sampleOffsets(lanesOf<U>(std::uint32_t(n)), openEnded, pattern, seeds);
}

}  // namespace WHITTED_ISA_NAMESPACE
}  // namespace whitted
