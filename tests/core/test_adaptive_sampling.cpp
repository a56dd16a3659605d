// Which tiles an adaptive render samples again (tracer/adaptive_sampling.h):
// a pixel's estimate speaks for its own tile and, kNearbyReach pixels deep,
// for the tiles beside it, carried to their sample counts.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "tracer/adaptive_sampling.h"

namespace whitted {
namespace {

// Two tiles of 16x16 side by side, 32x16 pixels, no estimate anywhere yet.
struct TwoTiles {
    std::vector<TileSamplingState> states = std::vector<TileSamplingState>(2);
    std::vector<PixelRect> rects = {{0, 0, 16, 16}, {16, 0, 16, 16}};
    PixelLargest pixels;
    TwoTiles(int leftSamples, int rightSamples) {
        pixels.width = 32, pixels.height = 16;
        pixels.codes.resize(32 * 16);
        states[0].samples = leftSamples, states[1].samples = rightSamples;
        for (TileSamplingState& s : states) s.pixels = 256;
    }
    // A pixel's estimate, as its tile's pass leaves it.
    void estimate(int x, int y, float codes) {
        pixels.at(x, y) = codes;
        TileErrorEstimate& e = states[x < 16 ? 0 : 1].estimate;
        e.largest = std::max(e.largest, double(codes));
    }
    void run() { estimateNearbyLargest(states, rects, kAdaptiveTileEdge, pixels); }
};

TEST(AdaptiveSampling, APixelBesideATileSpeaksForIt_AtThatTilesSamples) {
    TwoTiles t(8, 2);
    t.estimate(15 - (kNearbyReach - 1), 7, 40.0f);  // the deepest pixel that still speaks
    t.run();
    EXPECT_DOUBLE_EQ(t.states[0].nearbyLargest, 40.0);
    // At 2 samples, not 8: errors twice as large, sqrt(8 / 2).
    EXPECT_DOUBLE_EQ(t.states[1].nearbyLargest, 80.0);
    // Over Preview's sampling limit (51.2 codes): the right tile is sampled
    // again although its own pixels' estimates are all zero.
    const AdaptiveSampling limits{1e9, 51.2, 1024};
    EXPECT_EQ(tilesToRefine(t.states, limits), std::vector<int>{1});
}

TEST(AdaptiveSampling, APixelFurtherFromTheBorderDoesNot) {
    TwoTiles t(8, 2);
    t.estimate(15 - kNearbyReach, 7, 40.0f);
    t.run();
    EXPECT_DOUBLE_EQ(t.states[0].nearbyLargest, 40.0);
    EXPECT_DOUBLE_EQ(t.states[1].nearbyLargest, 0.0);
    EXPECT_TRUE(tilesToRefine(t.states, AdaptiveSampling{1e9, 51.2, 1024}).empty());
}

// A region rendered alone (a prediction's tile) has no tile beside it; the
// scene around it (AroundRegions) speaks for the whole render's, carried
// from its samples to the tile's. The right tile alone, at 2 samples.
TEST(AdaptiveSampling, WithNoTileBeside_TheSceneAroundTheRegionSpeaksForIt) {
    TwoTiles t(8, 2);
    t.states.erase(t.states.begin());
    t.rects.erase(t.rects.begin());
    AroundRegions around{Image(32, 16), t.pixels, 8};
    around.largest.at(15 - (kNearbyReach - 1), 7) = 40.0f;
    around.largest.at(15 - kNearbyReach, 3) = 90.0f;  // too far in to speak
    estimateNearbyLargest(t.states, t.rects, kAdaptiveTileEdge, t.pixels);
    EXPECT_DOUBLE_EQ(t.states[0].nearbyLargest, 0.0);
    estimateNearbyLargest(t.states, t.rects, kAdaptiveTileEdge, t.pixels, &around);
    EXPECT_DOUBLE_EQ(t.states[0].nearbyLargest, 80.0);  // 40 * sqrt(8 / 2)
}

TEST(AdaptiveSampling, ANeighbourWithFewerSamplesSpeaksForLess) {
    TwoTiles t(2, 32);
    t.estimate(15, 0, 40.0f);  // in the corner, beside the other tile
    t.run();
    EXPECT_DOUBLE_EQ(t.states[1].nearbyLargest, 10.0);  // 40 * sqrt(2 / 32)
    EXPECT_EQ(tilesToRefine(t.states, AdaptiveSampling{1e9, 20.0, 1024}), std::vector<int>{0});
}

// The estimate of a row: codes, not linear values; under one code a
// difference counts as itself (the chance it changes the rounded code), above
// as its square; 20 pixels, more than the 16 taken at a time.
TEST(AdaptiveSampling, HalvesEstimateOfARow_InCodes_EachPixelsLargest) {
    std::vector<float> before(3 * 20, 0.5f), after(3 * 20, 0.5f);
    after[3 * 17 + 1] = 0.0f;  // pixel 17's green: 187.52 codes from 0.5
    before[3 * 2] = 0.503f;    // pixel 2's red: about half a code above
    std::vector<float> largest(20, -1.0f);
    const TileErrorEstimate e = halvesEstimate(before.data(), after.data(), 20, largest.data());
    const double halfCode = 255.0 * (srgbEncode(before[6]) - srgbEncode(0.5f));
    EXPECT_NEAR(halfCode, 0.5, 0.1);
    EXPECT_EQ(e.values, 60);
    EXPECT_NEAR(e.largest, 187.52, 0.01);
    // The half code counts as itself, not squared.
    EXPECT_NEAR(e.squaredSum - e.largest * e.largest, halfCode, 0.005);
    EXPECT_NEAR(largest[17], 187.52, 0.01);
    EXPECT_NEAR(largest[2], halfCode, 0.005);  // srgbEncodeFast()'s codes
    EXPECT_EQ(largest[0], 0.0f);
    EXPECT_EQ(largest[19], 0.0f);
}

// A pixel whose samples all agree may still hold a sliver of its neighbour's
// colour: it is taken as off by one more sample of its most different
// neighbour's. A 5x5 picture, black but for one grey pixel at (2, 2); the
// tile is its first two columns, at 32 samples a pixel.
TEST(AdaptiveSampling, UnseenLargest_OneMoreSampleOfTheMostDifferentNeighbour) {
    Image image(5, 5);
    for (int c = 0; c < 3; ++c) image.pixel(2, 2)[c] = 0.3f;
    PixelLargest pixels;
    pixels.width = 5, pixels.height = 5;
    pixels.codes.assign(25, 0.0f);
    pixels.at(0, 0) = 50.0f;  // the halves' estimate, larger: kept
    const double largest = unseenLargest(image, {0, 0, 2, 5}, {0, 0, 5, 5}, 32, pixels);
    // 0.3 / 32 from black: 24.4 codes, near black where codes are dear.
    const double beside = 255.0 * srgbEncode(0.3f / 32.0f);
    EXPECT_NEAR(beside, 24.4, 0.1);
    for (int y : {1, 2, 3}) EXPECT_NEAR(pixels.at(1, y), beside, 0.01) << y;
    for (int y : {0, 4}) EXPECT_EQ(pixels.at(1, y), 0.0f) << y;  // (2, 2) is not beside them
    EXPECT_EQ(pixels.at(0, 2), 0.0f);
    EXPECT_EQ(pixels.at(0, 0), 50.0f);
    EXPECT_EQ(pixels.at(2, 2), 0.0f);  // outside the tile: left as it was
    EXPECT_DOUBLE_EQ(largest, 50.0);
    // The grey pixel itself, by its black neighbours: far less, where codes are cheap.
    unseenLargest(image, {2, 2, 1, 1}, {0, 0, 5, 5}, 32, pixels);
    const double grey = 255.0 * (srgbEncode(0.3f) - srgbEncode(0.3f * 31.0f / 32.0f));
    EXPECT_NEAR(grey, 2.1, 0.05);
    EXPECT_NEAR(pixels.at(2, 2), grey, 0.01);
}

// A region rendered alone (a prediction's tile) sees past its border only
// where it is told what lies there (RenderOptions::aroundRegions). The same
// picture, the region its right three columns: (2, 2) is its own, and the
// grey pixel beside it at (1, 2) is outside, shown only by `around`.
TEST(AdaptiveSampling, UnseenLargest_PastTheRegion_OnlyWhatTheSceneAroundItShows) {
    Image image(5, 5), around(5, 5);
    for (int c = 0; c < 3; ++c) around.pixel(1, 2)[c] = 0.3f;
    const PixelRect region{2, 0, 3, 5};
    PixelLargest pixels;
    pixels.width = 5, pixels.height = 5;
    pixels.codes.assign(25, 0.0f);
    EXPECT_EQ(unseenLargest(image, region, region, 32, pixels), 0.0);  // all black
    const double beside = 255.0 * srgbEncode(0.3f / 32.0f);
    EXPECT_NEAR(unseenLargest(image, region, region, 32, pixels, &around), beside, 0.01);
    for (int y : {1, 2, 3}) EXPECT_NEAR(pixels.at(2, y), beside, 0.01) << y;
    EXPECT_EQ(pixels.at(3, 2), 0.0f);  // not beside it
    // Inside the region its own pixels count, not `around`'s.
    for (int c = 0; c < 3; ++c) around.pixel(4, 4)[c] = 0.3f;
    pixels.codes.assign(25, 0.0f);
    unseenLargest(image, region, region, 32, pixels, &around);
    EXPECT_EQ(pixels.at(3, 3), 0.0f);
}

}  // namespace
}  // namespace whitted
