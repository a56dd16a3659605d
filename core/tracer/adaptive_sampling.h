// Rendering to an error instead of a sample count (RenderOptions::adaptive):
// how a tile's error is estimated from its own samples, and which tiles get
// more samples next. The renderer (renderer.cpp) runs the passes; the
// targets a user states become these limits in analysis/quality_target.h.
//
// The estimate. The mean A of a pixel's first n/2 samples and the mean B of
// the other n/2 are two independent estimates of the pixel, each with twice
// the variance of their mean F = (A + B) / 2, so (A - F)^2 = (A - B)^2 / 4
// estimates F's squared error. It is taken in sRGB codes, where the user sees
// it, from the picture as it was after the tile's last pass (A) and after this
// one (F): nothing more is stored. Stratified samples (progressiveSample())
// make the halves' difference, if anything, larger than F's error.
// A tile's first pass has two samples, so that it has halves to compare.
// Halves that agree can both have missed a sliver of the pixel; where the
// target limits the largest error, unseenLargest() covers that.
//
// Unless one sample may do (centresFirst, for loose targets with no limit on
// the largest error): then the first pass traces each pixel's centre, as a
// fixed one-sample render does, and a tile's error is estimated from the
// picture itself. A centre errs where its pixel holds an edge or a pattern
// finer than the pixel, which is where neighbouring centres differ. Its
// squared error is taken as kNeighbourShare of the squared differences
// between neighbouring pixels' codes: a half, the share where a pixel's
// contents are finer than the pixel (values independent from pixel to pixel,
// of spread s^2, differ by 2 s^2 on average and a centre errs by s^2). For
// one straight edge it would be a twelfth, so where edges dominate the
// estimate is too large. Against 256-sample references at the same depth it
// was 1.4 to 2.1 times the error on the shipped scenes and on the generated
// fields of test_quality_target, at 128x96, 320x240 and 640x480 (3 on
// coloured-shadows, whose soft shadows change smoothly from pixel to pixel;
// docs/design/quality-planning.md has the table). A thin line between two centres shows in
// neither, so a target with a limit on the largest error never starts with
// centres. A tile chosen after the centres starts over with two samples of
// the sequence: a centre is not one of its stratified samples.
//
// Rounding to 8-bit codes adds to the error: a value off by e < 1 code rounds
// to a different code with probability |e|, so a pixel's squared 8-bit error
// is about |e| there and e^2 above (codeSquaredError()).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "base/large_buffer_allocator.h"
#include "image/image.h"
#include "image/srgb.h"

namespace whitted {

struct AdaptiveSampling {
    // The 8-bit picture's mean squared error from sampling, in codes^2, that
    // the render stops under; and the largest error of a pixel's channel, in
    // codes (as displayDifference() counts them).
    double allowedMse = 0.0;
    double allowedLargest = 255.0;
    int maxSamples = 1024;      // a pixel's cap
    bool centresFirst = false;  // a first pass of pixel centres, estimated from neighbours
};

// Whether the render keeps each pixel's estimate of its largest error
// (PixelLargest), and so looks at its neighbours (unseenLargest()).
inline bool limitsLargest(const AdaptiveSampling& limits) {
    return limits.allowedLargest < 255.0;
}

// An adaptive render's tile edge (RenderOptions::tileSize is for fixed
// renders). Samples are chosen per tile: in tiles of 32 one pixel's estimate
// took a thousand pixels to more samples; in tiles of 16, with the pixels two
// beyond a tile vouching for it (kNearbyReach), every measured target of
// docs/design/quality-planning.md was met as before with 0.76 to 1.03 times the rays. 16 is
// still a whole packet (simd.h) with AVX-512.
inline constexpr int kAdaptiveTileEdge = 16;
// How far beyond its tile, in pixels, a pixel's estimate speaks for it
// (estimateNearbyLargest()). Without it, in tiles of 16, a pixel of seed.json
// at Final was 33 codes off (16 allowed) and one of field.json at Preview 74
// (64 allowed); with it, 14 and 64.
inline constexpr int kNearbyReach = 2;

inline constexpr double kNeighbourShare = 0.5;

// Per tile, after the render.
struct AdaptiveOutcome {
    double meanSamples = 0.0;  // per pixel over the picture
    int fewestSamples = 0, mostSamples = 0;
    double estimatedMse = 0.0;      // codes^2, from sampling, as the render stopped
    double estimatedLargest = 0.0;  // codes
    int tiles = 0;
    int tilesAtCap = 0;  // stopped by maxSamples with their error still above a limit
    int passes = 0;      // full-size passes over some tiles
};

// The expected squared error of an 8-bit code whose exact value is off by e codes.
inline double codeSquaredError(double e) {
    const double a = std::fabs(e);
    return a < 1.0 ? a : a * a;
}

// A tile's error estimate, summed over its pixels' channels.
struct TileErrorEstimate {
    double squaredSum = 0.0;  // codeSquaredError() of each channel's estimate
    double largest = 0.0;     // codes
    long values = 0;          // channels estimated

    double add(double e) {
        squaredSum += codeSquaredError(e);
        largest = std::max(largest, std::fabs(e));
        ++values;
        return std::fabs(e);
    }
    void add(const TileErrorEstimate& part) {
        squaredSum += part.squaredSum;
        largest = std::max(largest, part.largest);
        values += part.values;
    }
    double mse() const { return values ? squaredSum / double(values) : 0.0; }
};

// The estimate of a row of `pixels` pixels whose picture values went from
// `before` (n/2 samples) to `after` (n), three channels a pixel; each pixel's
// largest over its channels, in codes, into `largestOfPixel` unless null.
// A row at a time: taken pixel by pixel, with a call for each channel's
// code, it was a sixth of an adaptive render's time.
TileErrorEstimate halvesEstimate(const float* before, const float* after, int pixels,
                                 float* largestOfPixel);

// What the renderer knows of a tile between passes.
struct TileSamplingState {
    int samples = 0;  // per pixel so far
    int pixels = 0;
    TileErrorEstimate estimate;  // of its last pass
    // The largest error its pixels may have, at its samples, judged also by
    // pixels just outside it (estimateNearbyLargest()); codes.
    double nearbyLargest = 0.0;
};

// Each pixel's largest estimated error over its channels, in codes, as its
// tile's last pass left it (zero where none was estimated).
struct PixelLargest {
    int width = 0, height = 0;
    std::vector<float, LargeBufferAllocator<float>> codes;  // zero pages until rendered
    float& at(int x, int y) { return codes[std::size_t(y) * width + x]; }
    float at(int x, int y) const { return codes[std::size_t(y) * width + x]; }
};

// The picture around a render's regions as the whole render would show it,
// for the estimates that look past a tile's border, which a region rendered
// alone cannot (RenderOptions::aroundRegions): a sample of the picture's
// tiles then takes the samples it takes in the whole (target_prediction.h).
struct AroundRegions {
    Image image;           // the render's size; read within kNearbyReach of the regions
    PixelLargest largest;  // each of those pixels' estimate of its largest error...
    int samples = 0;       // ...at these samples a pixel
};

// Sets each tile's nearbyLargest: the largest of its pixels' estimates and
// of those within kNearbyReach pixels outside it, a neighbour's carried to
// the tile's samples as errors go, with the inverse square root of the
// samples. A pixel's estimate is one draw of a noisy quantity, small by
// chance a quarter of the time; an edge or a caustic that crosses a tile
// border shows in the pixels on both sides, so the pixels beside a tile
// vouch for its own. `rects[i]` are tile i's pixels, on a grid of `edge`.
// Where no tile is rendered next to one, `around`'s pixels vouch, if given.
void estimateNearbyLargest(std::vector<TileSamplingState>& tiles,
                           const std::vector<PixelRect>& rects, int edge,
                           const PixelLargest& pixels, const AroundRegions* around = nullptr);

// What a pixel's samples may all have missed. Where a feature covers a
// sliver of a pixel, a corner of a checker square or the rim of a ball, no
// sample may land on it: its samples then agree, the halves do too, and the
// pixel is estimated as exact where it is off by the sliver. So each pixel
// of `tile` is also taken as off by what one more of its `samples` would
// change, were that sample the colour of its most different neighbour, and
// its estimate in `pixels` raised to that; returns the tile's largest, in
// codes. It is held to the same limit as the halves' estimate, margin and
// all: held to the target's own limit instead, an untuned field's Final at
// 640x480 still missed (docs/design/quality-planning.md, "Known limits").
// After a pass, with its neighbours rendered: they are the colours a sliver
// of it may have. Only neighbours within `rendered` count: outside a
// render's regions the picture is black, not the scene. Unless `around`
// shows the scene there (RenderOptions::aroundRegions): then neighbours
// past `rendered` are its pixels.
double unseenLargest(const Image& image, const PixelRect& tile, const PixelRect& rendered,
                     int samples, PixelLargest& pixels, const Image* around = nullptr);

// The error of the centre samples in `tile` of `image`, from the differences
// between each pixel and its right and lower neighbours inside the tile (a
// tile is estimated from its own pixels only: its neighbours may still be
// rendering). A tile of one pixel has none and is estimated as 255 codes off.
TileErrorEstimate centreSampleEstimate(const Image& image, const PixelRect& tile);

// The picture's estimated mean squared error: its tiles' estimates weighted by pixels.
double estimatedPictureMse(const std::vector<TileSamplingState>& tiles);

// The tiles whose samples the next pass doubles, in index order: every tile
// whose largest error is over the limit, then the tiles that cut the most
// error per sample (a doubling roughly halves a tile's squared error) until
// the picture's estimate would be under the limit. Tiles at maxSamples are
// never chosen. Empty: the render is done.
std::vector<int> tilesToRefine(const std::vector<TileSamplingState>& tiles,
                               const AdaptiveSampling& limits);

// The outcome of the finished tiles.
AdaptiveOutcome adaptiveOutcome(const std::vector<TileSamplingState>& tiles,
                                const AdaptiveSampling& limits, int passes);

}  // namespace whitted
