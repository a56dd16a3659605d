// Tests for core/sampling.*: the pixel centre for one sample, stratified samples in
// [0,1)^2 otherwise, and every sample a pure function of (index, count, seed).
#include <cmath>
#include <cstdio>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tracer/sampling.h"

namespace whitted {
namespace {

// The seeds tried: some real pixel seeds, a few extremes, and random ones (printed).
std::vector<std::uint32_t> seedsToTry() {
    std::vector<std::uint32_t> seeds = {0u, 1u, 0xffffffffu, 0x80000000u};
    for (int j : {0, 1, 239, 16383})
        for (int i : {0, 1, 319, 16383}) seeds.push_back(pixelSeed(i, j));
    const unsigned seed = std::random_device{}();
    std::printf("random seed for the seed list: %u\n", seed);
    std::mt19937 rng(seed);
    for (int k = 0; k < 40; ++k) seeds.push_back(rng());
    return seeds;
}

// The positions themselves, as the first version of the sampler gave them
// (before the renderer made them for a packet's pixels at once): a render of
// a scene is the same picture in every version, and a farm's regions rendered
// by two versions still fit together.
TEST(Sampling, Positions_AreThoseOfTheFirstVersion) {
    struct Expected {
        int s, count;
        std::uint32_t seed;
        double u, v;
    };
    for (const Expected& e :
         {Expected{3, 8, 0x1234u, 0x1.16458456p-4, 0x1.7537fac0cp-1},
          Expected{17, 32, 0xaee25ab0u, 0x1.844447d249249p-4, 0x1.02879e401p-1},
          Expected{5, 1000, 0xffffffffu, 0x1.beb0c00745d18p-1, 0x1.f00670f3a3d71p-1}}) {
        const SubPixel p = subPixelSample(e.s, e.count, e.seed);
        EXPECT_EQ(p.u, e.u) << "sample " << e.s << " of " << e.count;
        EXPECT_EQ(p.v, e.v) << "sample " << e.s << " of " << e.count;
    }
    EXPECT_EQ(pixelSeed(100, 50), 0xaee25ab0u);
    for (const Expected& e : {Expected{0, 0, 0x1234u, 0x1.f2d26cp-2, 0x1.e787ecp-1},
                              Expected{37, 0, 0xaee25ab0u, 0x1.31f06p-3, 0x1.d7a324p-1},
                              Expected{4095, 0, 0xffffffffu, 0x1.0e2096p-1, 0x1.62f678p-1}}) {
        const SubPixel p = progressiveSample(e.s, e.seed);
        EXPECT_EQ(p.u, e.u) << "sequence sample " << e.s;
        EXPECT_EQ(p.v, e.v) << "sequence sample " << e.s;
    }
}

TEST(Sampling, OneSample_IsPixelCentre) {
    for (std::uint32_t seed : {0u, 7u, pixelSeed(3, 4), 0xffffffffu}) {
        const SubPixel p = subPixelSample(0, 1, seed);
        EXPECT_EQ(p.u, 0.5) << "seed " << seed;
        EXPECT_EQ(p.v, 0.5) << "seed " << seed;
    }
}

class SamplingStratified : public ::testing::TestWithParam<int> {};
class SamplingSquareCount : public ::testing::TestWithParam<int> {};

TEST_P(SamplingStratified, SamplesInUnitSquare_OnePerRowOfHeightOneOverN) {
    const int n = GetParam();
    for (const std::uint32_t seed : seedsToTry()) {
        SCOPED_TRACE("pixel seed " + std::to_string(seed) + ", count " + std::to_string(n));
        std::vector<int> rows(n, 0);
        for (int s = 0; s < n; ++s) {
            const SubPixel p = subPixelSample(s, n, seed);
            ASSERT_GE(p.u, 0.0) << "sample " << s;
            ASSERT_LT(p.u, 1.0) << "sample " << s;
            ASSERT_GE(p.v, 0.0) << "sample " << s;
            ASSERT_LT(p.v, 1.0) << "sample " << s;
            // Row k is [k/n, (k+1)/n).
            const int row = int(std::floor(p.v * n));
            ASSERT_GE(row, 0);
            ASSERT_LT(row, n);
            ++rows[row];
        }
        for (int k = 0; k < n; ++k) EXPECT_EQ(rows[k], 1) << "row " << k;
    }
}

TEST_P(SamplingSquareCount, AlsoOnePerColumnAndPerGridCell) {
    const int n = GetParam();
    const int m = int(std::lround(std::sqrt(double(n))));
    ASSERT_EQ(m * m, n) << "instantiate with square counts only";
    for (const std::uint32_t seed : seedsToTry()) {
        SCOPED_TRACE("pixel seed " + std::to_string(seed));
        std::vector<int> columns(n, 0), cells(n, 0);
        for (int s = 0; s < n; ++s) {
            const SubPixel p = subPixelSample(s, n, seed);
            ++columns[int(std::floor(p.u * n))];
            // And one per cell of the m x m grid (2D stratification).
            ++cells[int(std::floor(p.v * m)) * m + int(std::floor(p.u * m))];
        }
        for (int k = 0; k < n; ++k) {
            EXPECT_EQ(columns[k], 1) << "column " << k;
            EXPECT_EQ(cells[k], 1) << "cell " << k;
        }
    }
}

TEST_P(SamplingStratified, SameIndexCountAndSeed_GiveSameValue) {
    const int n = GetParam();
    for (const std::uint32_t seed : seedsToTry()) {
        std::vector<SubPixel> first;
        for (int s = 0; s < n; ++s) first.push_back(subPixelSample(s, n, seed));
        // Asked again, backwards: nothing depends on call order or state.
        for (int s = n - 1; s >= 0; --s) {
            const SubPixel again = subPixelSample(s, n, seed);
            EXPECT_EQ(again.u, first[s].u) << "seed " << seed << ", sample " << s;
            EXPECT_EQ(again.v, first[s].v) << "seed " << seed << ", sample " << s;
        }
    }
}

TEST_P(SamplingStratified, DifferentPixels_GetDifferentPatterns) {
    const int n = GetParam();
    // Jittered, not a fixed grid: over 16 neighbouring pixels sample 0 takes many values.
    std::set<std::pair<double, double>> firstSamples;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            const SubPixel p = subPixelSample(0, n, pixelSeed(i, j));
            firstSamples.insert({p.u, p.v});
        }
    EXPECT_GE(firstSamples.size(), 12u);
}

INSTANTIATE_TEST_SUITE_P(Counts, SamplingStratified, ::testing::Values(2, 4, 5, 16, 64, 100, 1000),
                         [](const ::testing::TestParamInfo<int>& info) {
                             return std::string("N").append(std::to_string(info.param));
                         });

INSTANTIATE_TEST_SUITE_P(Counts, SamplingSquareCount, ::testing::Values(4, 16, 64, 256),
                         [](const ::testing::TestParamInfo<int>& info) {
                             return std::string("N").append(std::to_string(info.param));
                         });

// The open-ended sequence of adaptive renders: its first 2^k samples put one
// sample in every cell of every grid of 2^a x 2^b cells with a + b = k, for
// every k, so a tile that stops at any power of two is evenly covered.
TEST(Sampling, ProgressiveSample_EveryPowerOfTwoPrefixIsStratifiedInEveryGrid) {
    for (const std::uint32_t seed : seedsToTry()) {
        SCOPED_TRACE("pixel seed " + std::to_string(seed));
        for (int k = 0; k <= 8; ++k) {
            const int n = 1 << k;
            for (int a = 0; a <= k; ++a) {
                const int columns = 1 << a, rows = 1 << (k - a);
                std::vector<int> cells(n, 0);
                for (int s = 0; s < n; ++s) {
                    const SubPixel p = progressiveSample(s, seed);
                    ASSERT_GE(p.u, 0.0);
                    ASSERT_LT(p.u, 1.0);
                    ASSERT_GE(p.v, 0.0);
                    ASSERT_LT(p.v, 1.0);
                    ++cells[int(p.v * rows) * columns + int(p.u * columns)];
                }
                for (int c = 0; c < n; ++c)
                    ASSERT_EQ(cells[c], 1)
                        << n << " samples, " << columns << "x" << rows << " grid, cell " << c;
            }
        }
    }
}

TEST(Sampling, ProgressiveSample_IsAPureFunctionAndDiffersBetweenPixels) {
    std::set<std::pair<double, double>> firstSamples;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            const SubPixel p = progressiveSample(0, pixelSeed(i, j));
            const SubPixel again = progressiveSample(0, pixelSeed(i, j));
            EXPECT_EQ(p.u, again.u);
            EXPECT_EQ(p.v, again.v);
            firstSamples.insert({p.u, p.v});
        }
    EXPECT_GE(firstSamples.size(), 12u);
}

TEST(Sampling, PixelSeed_IsDeterministicAndDistinguishesNeighbours) {
    EXPECT_EQ(pixelSeed(12, 34), pixelSeed(12, 34));
    std::set<std::uint32_t> seeds;
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i) seeds.insert(pixelSeed(i, j));
    EXPECT_EQ(seeds.size(), 64u * 64u) << "two pixels of a 64x64 block share a seed";
    EXPECT_NE(pixelSeed(1, 0), pixelSeed(0, 1));
}

TEST(Sampling, MeanOfManyStratifiedSamples_IsNearPixelCentre) {
    // Stratified in v with one sample per 1/N row: the mean v is within 1/(2N) of 0.5.
    const int n = 256;
    double su = 0, sv = 0;
    for (int s = 0; s < n; ++s) {
        const SubPixel p = subPixelSample(s, n, pixelSeed(5, 9));
        su += p.u;
        sv += p.v;
    }
    EXPECT_NEAR(sv / n, 0.5, 0.5 / n + 1e-12);
    EXPECT_NEAR(su / n, 0.5, 0.02);
}

}  // namespace
}  // namespace whitted
