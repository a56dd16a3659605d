#include "tracer/sampling.h"

#include <cmath>

namespace whitted {
namespace {

// A hash-based permutation of [0, l) (Kensler, listing 2).
std::uint32_t permute(std::uint32_t i, std::uint32_t l, std::uint32_t p) {
    std::uint32_t w = l - 1;
    w |= w >> 1;
    w |= w >> 2;
    w |= w >> 4;
    w |= w >> 8;
    w |= w >> 16;
    do {
        i ^= p;
        i *= 0xe170893d;
        i ^= p >> 16;
        i ^= (i & w) >> 4;
        i ^= p >> 8;
        i *= 0x0929eb3f;
        i ^= p >> 23;
        i ^= (i & w) >> 1;
        i *= 1 | p >> 27;
        i *= 0x6935fa69;
        i ^= (i & w) >> 11;
        i *= 0x74dcb303;
        i ^= (i & w) >> 2;
        i *= 0x9e501cc3;
        i ^= (i & w) >> 2;
        i *= 0xc860a3df;
        i &= w;
        i ^= i >> 5;
    } while (i >= l);
    return (i + p) % l;
}

// A hashed value in [0, 1) (Kensler, listing 3).
double randomUnit(std::uint32_t i, std::uint32_t p) {
    i ^= p;
    i ^= i >> 17;
    i ^= i >> 10;
    i *= 0xb36534e5;
    i ^= i >> 12;
    i ^= i >> 21;
    i *= 0x93fc4795;
    i ^= 0xdf6e307f;
    i ^= i >> 17;
    i *= 1 | p >> 18;
    return i * (1.0 / 4294967296.0);
}

std::uint32_t reverseBits(std::uint32_t x) {
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    return ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
}

// Owen scrambling of a value in [0, 2^32) read as a binary fraction: each bit
// is flipped by a hash of the bits above it (Laine and Karras's permutation,
// applied to the reversed bits so that "above" becomes "below").
std::uint32_t owenScramble(std::uint32_t x, std::uint32_t seed) {
    x = reverseBits(x);
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return reverseBits(x);
}

// Sobol's second dimension: the bits of `index` select direction numbers
// v_0 = 1/2, v_k = v_{k-1} xor v_{k-1}/2 (the first dimension is the index
// with its bits reversed).
std::uint32_t sobolSecond(std::uint32_t index) {
    std::uint32_t v = 0x80000000u, x = 0;
    for (; index != 0; index >>= 1, v ^= v >> 1)
        if (index & 1u) x ^= v;
    return x;
}

std::uint32_t hashSeed(std::uint32_t seed, std::uint32_t salt) {
    seed ^= salt;
    seed *= 0x9e3779b9u;
    seed ^= seed >> 16;
    seed *= 0x85ebca6bu;
    return seed ^ (seed >> 13);
}

}  // namespace

SubPixel progressiveSample(int s, std::uint32_t seed) {
    const auto index = static_cast<std::uint32_t>(s);
    const std::uint32_t x = owenScramble(reverseBits(index), hashSeed(seed, 0x2c1b3c6du));
    const std::uint32_t y = owenScramble(sobolSecond(index), hashSeed(seed, 0x297a2d39u));
    // The top 24 bits: exact in float too, and below 1.
    constexpr double kUnit = 1.0 / 16777216.0;
    return {(x >> 8) * kUnit, (y >> 8) * kUnit};
}

std::uint32_t pixelSeed(int i, int j) {
    // PCG-style integer hash of the packed coordinates (both < 2^14 + 1).
    std::uint32_t x = (static_cast<std::uint32_t>(j) << 15) ^ static_cast<std::uint32_t>(i);
    x = x * 747796405u + 2891336453u;
    const std::uint32_t word = ((x >> ((x >> 28u) + 4u)) ^ x) * 277803737u;
    return (word >> 22u) ^ word;
}

SubPixel subPixelSample(int s, int count, std::uint32_t seed) {
    if (count <= 1) return {0.5, 0.5};
    // An m x n grid of strata with m*n >= count, each sample also alone in its
    // 1/count row: stratified in 2D and in each axis.
    const auto N = static_cast<std::uint32_t>(count);
    const auto m = static_cast<std::uint32_t>(std::sqrt(static_cast<double>(count)));
    const std::uint32_t n = (N + m - 1) / m;
    const std::uint32_t si = permute(static_cast<std::uint32_t>(s), N, seed * 0x51633e2d);
    const std::uint32_t sx = permute(si % m, m, seed * 0x68bc21eb);
    const std::uint32_t sy = permute(si / m, n, seed * 0x02e5be93);
    const double jx = randomUnit(si, seed * 0x967a889b);
    const double jy = randomUnit(si, seed * 0x368cc8b7);
    return {(sx + (sy + jx) / n) / m, (si + jy) / N};
}

}  // namespace whitted
