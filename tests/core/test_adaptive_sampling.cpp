// Which tiles an adaptive render samples again (tracer/adaptive_sampling.h):
// a pixel's estimate speaks for its own tile and, kNearbyReach pixels deep,
// for the tiles beside it, carried to their sample counts.
#include <algorithm>
#include <cmath>
#include <random>
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

// unseenLargest() reads its neighbours a row at a time; what it gives is the
// definition taken pixel by pixel: for each channel, one more sample of the
// lowest and of the highest of the pixel and its eight neighbours, within
// the rendered pixels (or `around`'s past them). Checked on a noisy 37x29
// picture, tiles at each edge and corner of the picture and of a region.
float unseenOfPixel(const Image& image, int x, int y, const PixelRect& rendered, int samples,
                    const Image* around) {
    const PixelRect seen = around ? PixelRect{0, 0, image.width, image.height} : rendered;
    const float share = 1.0f / float(samples);
    float largest = 0.0f;
    for (int c = 0; c < 3; ++c) {
        const float own = image.pixel(x, y)[c];
        for (int ny = y - 1; ny <= y + 1; ++ny)
            for (int nx = x - 1; nx <= x + 1; ++nx) {
                if (!contains(seen, nx, ny)) continue;
                const Image& from = around && !contains(rendered, nx, ny) ? *around : image;
                const float moved = own + share * (from.pixel(nx, ny)[c] - own);
                largest = std::max(largest,
                                   255.0f * std::fabs(srgbEncodeFast(moved) - srgbEncodeFast(own)));
            }
    }
    return largest;
}

TEST(AdaptiveSampling, UnseenLargest_RowByRow_AsPixelByPixel) {
    Image image(37, 29), around(37, 29);
    std::mt19937 random(7);
    std::uniform_real_distribution<float> value(0.0f, 1.2f);
    for (int y = 0; y < 29; ++y)
        for (int x = 0; x < 37; ++x)
            for (int c = 0; c < 3; ++c) {
                image.pixel(x, y)[c] = value(random);
                around.pixel(x, y)[c] = value(random);
            }
    const PixelRect whole{0, 0, 37, 29}, region{5, 3, 20, 17};
    struct Case {
        PixelRect tile, rendered;
        const Image* around;
    };
    const std::vector<Case> cases = {
        {{0, 0, 16, 16}, whole, nullptr},  {{32, 16, 5, 13}, whole, nullptr},
        {{16, 0, 16, 1}, whole, nullptr},  {{5, 3, 16, 16}, region, nullptr},
        {{21, 19, 4, 1}, region, nullptr}, {{5, 3, 16, 16}, region, &around},
        {{21, 3, 4, 17}, region, &around}, {{36, 28, 1, 1}, whole, nullptr}};
    for (const Case& k : cases) {
        PixelLargest pixels;
        pixels.width = 37, pixels.height = 29;
        pixels.codes.assign(37 * 29, 0.0f);
        const double largest = unseenLargest(image, k.tile, k.rendered, 8, pixels, k.around);
        float expectedLargest = 0.0f;
        for (int y = k.tile.y; y < k.tile.y + k.tile.height; ++y)
            for (int x = k.tile.x; x < k.tile.x + k.tile.width; ++x) {
                const float expected = unseenOfPixel(image, x, y, k.rendered, 8, k.around);
                ASSERT_EQ(pixels.at(x, y), expected) << x << ", " << y;
                expectedLargest = std::max(expectedLargest, expected);
            }
        EXPECT_EQ(largest, expectedLargest);
        EXPECT_GT(largest, 1.0);  // noise: every pixel has something to hide
    }
}

}  // namespace
}  // namespace whitted
