#include "tracer/adaptive_sampling.h"

#include <cstdint>
#include <cstdlib>

namespace whitted {

namespace {

// The largest estimate of tile j's pixels within `area`, carried to `samples`.
double largestWithin(const PixelLargest& pixels, const PixelRect& area, const PixelRect& tile,
                     double scale) {
    const int x0 = std::max(area.x, tile.x),
              x1 = std::min(area.x + area.width, tile.x + tile.width);
    const int y0 = std::max(area.y, tile.y),
              y1 = std::min(area.y + area.height, tile.y + tile.height);
    float largest = 0.0f;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) largest = std::max(largest, pixels.at(x, y));
    return largest * scale;
}

}  // namespace

void estimateNearbyLargest(std::vector<TileSamplingState>& tiles,
                           const std::vector<PixelRect>& rects, int edge,
                           const PixelLargest& pixels, const AroundRegions* around) {
    const int columns = (pixels.width + edge - 1) / edge;
    const int rows = (pixels.height + edge - 1) / edge;
    std::vector<int> tileOfCell(std::size_t(columns) * rows, -1);
    for (std::size_t i = 0; i < rects.size(); ++i)
        tileOfCell[std::size_t(rects[i].y / edge) * columns + rects[i].x / edge] = int(i);
    const int reach = std::min(kNearbyReach, edge);  // within the next tiles
    for (std::size_t i = 0; i < tiles.size(); ++i) {
        const PixelRect& r = rects[i];
        const PixelRect area{r.x - reach, r.y - reach, r.width + 2 * reach, r.height + 2 * reach};
        const int column = r.x / edge, row = r.y / edge;
        // Its own pixels' largest is its estimate's.
        double largest = tiles[i].estimate.largest;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int x = column + dx, y = row + dy;  // the neighbour's cell
                if ((dx == 0 && dy == 0) || x < 0 || y < 0 || x >= columns || y >= rows) continue;
                const int j = tileOfCell[std::size_t(y) * columns + x];
                if (tiles[i].samples <= 0) continue;
                if (j < 0) {
                    if (!around) continue;
                    const PixelRect cell{x * edge, y * edge,
                                         std::min(edge, pixels.width - x * edge),
                                         std::min(edge, pixels.height - y * edge)};
                    const double scale = std::sqrt(double(around->samples) / tiles[i].samples);
                    largest = std::max(largest, largestWithin(around->largest, area, cell, scale));
                    continue;
                }
                const double scale = std::sqrt(double(tiles[j].samples) / tiles[i].samples);
                // Its pixels cannot raise what was found already.
                if (tiles[j].estimate.largest * scale <= largest) continue;
                largest = std::max(largest, largestWithin(pixels, area, rects[j], scale));
            }
        tiles[i].nearbyLargest = largest;
    }
}

namespace {

// Differences between neighbouring pixels' codes: the sum of their squares,
// how many are 1, the largest.
struct CodePairs {
    std::int64_t squares = 0;
    int ones = 0, largest = 0;
};

// The pairs a[k], b[k] for k < count (kCount, where it is known). Summed in
// 32 bits, a chunk at a time, and for a full tile's row (48 codes) with its
// count known, so the loop runs on whole vectors with no scalar remainder:
// with 45 pairs a row and 64-bit sums it took 2.7 times as long.
template <int kCount>
void addPairs(const std::uint8_t* a, const std::uint8_t* b, int count, CodePairs& pairs) {
    if constexpr (kCount > 0) count = kCount;
    constexpr int kChunk = 8192;  // 8192 * 255^2 fits in 31 bits
    for (int start = 0; start < count; start += kChunk) {
        const int end = std::min(count, start + kChunk);
        int squares = 0, ones = 0, largest = 0;
        for (int k = start; k < end; ++k) {
            const int d = std::abs(int(a[k]) - int(b[k]));
            squares += d * d;
            ones += d == 1 ? 1 : 0;
            largest = std::max(largest, d);
        }
        pairs.squares += squares;
        pairs.ones += ones;
        pairs.largest = std::max(pairs.largest, largest);
    }
}

// Each row's codes followed by its last pixel's again: the right neighbours
// of a row are then `stride` pairs like the lower ones, the last a difference
// of 0, which adds nothing.
template <int kStride>
CodePairs tilePairs(const std::uint8_t* codes, int stride, int h) {
    CodePairs pairs;
    const int padded = stride + 3;
    for (int y = 0; y < h; ++y) {
        const std::uint8_t* row = codes + std::size_t(y) * padded;
        addPairs<kStride>(row, row + 3, stride, pairs);                      // right neighbours
        if (y + 1 < h) addPairs<kStride>(row, row + padded, stride, pairs);  // lower neighbours
    }
    return pairs;
}

}  // namespace

TileErrorEstimate centreSampleEstimate(const Image& image, const PixelRect& tile) {
    // A centre's error, in codes, per code of difference to a neighbour: under
    // one code for a difference of one (counted as |e|), over one from two up
    // (counted as e^2), so the pairs' squared errors are two integer sums.
    static_assert(kNeighbourShare >= 0.25 && kNeighbourShare < 1.0);
    static const double errorPerDifference = std::sqrt(kNeighbourShare);
    // The 8-bit codes the user sees, each looked up once. Integer sums, not a
    // codeSquaredError() per pair: summed in doubles, the pairs took twice as
    // long as tracing the centres of a simple scene.
    const int w = tile.width, h = tile.height, stride = 3 * w, padded = stride + 3;
    std::vector<std::uint8_t> codes(std::size_t(padded) * h);
    for (int y = 0; y < h; ++y) {
        std::uint8_t* row = codes.data() + std::size_t(y) * padded;
        srgbEncode8(image.pixel(tile.x, tile.y + y), stride, row);
        if (w > 0) std::copy(row + stride - 3, row + stride, row + stride);
    }
    constexpr int kFullRow = 3 * kAdaptiveTileEdge;
    const CodePairs pairs = stride == kFullRow ? tilePairs<kFullRow>(codes.data(), stride, h)
                                               : tilePairs<0>(codes.data(), stride, h);
    TileErrorEstimate estimate;
    estimate.values = long(h) * (stride - 3) + long(h - 1) * stride;
    estimate.squaredSum = kNeighbourShare * double(pairs.squares - pairs.ones) +
                          errorPerDifference * double(pairs.ones);
    estimate.largest = errorPerDifference * pairs.largest;
    if (estimate.values == 0) estimate.add(255.0);
    return estimate;
}

namespace {

// One row of the neighbours unseenLargest() reads around a tile: the tile's
// columns and one more on each side, within `seen` (a column or row past it
// stands in by its nearest, which leaves a lowest and a highest as they
// are), from `around` past `rendered` when it is given.
void neighbourRow(const Image& image, const PixelRect& tile, int y, const PixelRect& seen,
                  const PixelRect& rendered, const Image* around, float* row) {
    y = std::clamp(y, seen.y, seen.y + seen.height - 1);
    for (int x = tile.x - 1; x <= tile.x + tile.width; ++x) {
        const int from = std::clamp(x, seen.x, seen.x + seen.width - 1);
        const float* pixel =
            around && !contains(rendered, from, y) ? around->pixel(from, y) : image.pixel(from, y);
        std::copy(pixel, pixel + 3, row + 3 * (x - tile.x + 1));
    }
}

}  // namespace

double unseenLargest(const Image& image, const PixelRect& tile, const PixelRect& rendered,
                     int samples, PixelLargest& pixels, const Image* around) {
    const float share = 1.0f / float(std::max(1, samples));
    // Where the neighbours may be: the rendered pixels, or the whole picture
    // with `around` standing in past them.
    const PixelRect seen = around ? PixelRect{0, 0, image.width, image.height} : rendered;
    const std::size_t values = 3 * std::size_t(tile.width), wide = values + 6;
    // Three rows of neighbours, the one above the row at hand first; each row
    // read once. Then, channel by channel, the lowest and highest of the
    // column of three, and of three such columns side by side.
    std::vector<float> rows(3 * wide), columnLow(wide), columnHigh(wide);
    float* above = rows.data();
    float* at = above + wide;
    float* below = at + wide;
    neighbourRow(image, tile, tile.y - 1, seen, rendered, around, above);
    neighbourRow(image, tile, tile.y, seen, rendered, around, at);
    // What one more sample of the lowest and of the highest neighbour would
    // make of each value, as the user sees them. Where a neighbourhood is
    // flat, the value is its own and moves by nothing.
    std::vector<float> own(values), toLow(values), toHigh(values), moved(values);
    float tileLargest = 0.0f;
    for (int y = tile.y; y < tile.y + tile.height; ++y) {
        neighbourRow(image, tile, y + 1, seen, rendered, around, below);
        for (std::size_t i = 0; i < wide; ++i) {
            columnLow[i] = std::min({above[i], at[i], below[i]});
            columnHigh[i] = std::max({above[i], at[i], below[i]});
        }
        const float* value = at + 3;
        for (std::size_t i = 0; i < values; ++i) {
            const float low = std::min({columnLow[i], columnLow[i + 3], columnLow[i + 6]});
            const float high = std::max({columnHigh[i], columnHigh[i + 3], columnHigh[i + 6]});
            toLow[i] = value[i] + share * (low - value[i]);
            toHigh[i] = value[i] + share * (high - value[i]);
        }
        srgbEncodeFast(value, values, own.data());
        srgbEncodeFast(toLow.data(), values, toLow.data());
        srgbEncodeFast(toHigh.data(), values, toHigh.data());
        for (std::size_t i = 0; i < values; ++i)
            moved[i] =
                255.0f * std::max(std::fabs(toLow[i] - own[i]), std::fabs(toHigh[i] - own[i]));
        for (int x = 0; x < tile.width; ++x) {
            float& estimate = pixels.at(tile.x + x, y);
            estimate = std::max({estimate, moved[3 * x], moved[3 * x + 1], moved[3 * x + 2]});
            tileLargest = std::max(tileLargest, estimate);
        }
        std::swap(above, at);  // the next row's three: this row's, the one below, a new one
        std::swap(at, below);
    }
    return tileLargest;
}

TileErrorEstimate halvesEstimate(const float* before, const float* after, int pixels,
                                 float* largestOfPixel) {
    constexpr int kChunk = 16;  // pixels: a tile's row, on the stack
    float codesBefore[3 * kChunk], codesAfter[3 * kChunk];
    TileErrorEstimate estimate;
    for (int start = 0; start < pixels; start += kChunk) {
        const int count = std::min(kChunk, pixels - start);
        srgbEncodeFast(before + 3 * start, 3 * count, codesBefore);
        srgbEncodeFast(after + 3 * start, 3 * count, codesAfter);
        for (int i = 0; i < count; ++i) {
            double largest = 0.0;
            for (int c = 0; c < 3; ++c) {
                const double e =
                    255.0 * double(codesBefore[3 * i + c]) - 255.0 * double(codesAfter[3 * i + c]);
                largest = std::max(largest, estimate.add(e));
            }
            if (largestOfPixel) largestOfPixel[start + i] = float(largest);
        }
    }
    return estimate;
}

double estimatedPictureMse(const std::vector<TileSamplingState>& tiles) {
    double weighted = 0.0, pixels = 0.0;
    for (const TileSamplingState& t : tiles) {
        weighted += t.estimate.mse() * t.pixels;
        pixels += t.pixels;
    }
    return pixels > 0.0 ? weighted / pixels : 0.0;
}

std::vector<int> tilesToRefine(const std::vector<TileSamplingState>& tiles,
                               const AdaptiveSampling& limits) {
    const int count = static_cast<int>(tiles.size());
    std::vector<char> chosen(count, 0);
    double pixels = 0.0, squared = 0.0;  // the picture's, as the chosen tiles would leave it
    for (const TileSamplingState& t : tiles) {
        pixels += t.pixels;
        squared += t.estimate.mse() * t.pixels;
    }
    auto choose = [&](int i) {
        chosen[i] = 1;
        squared -= tiles[i].estimate.mse() * tiles[i].pixels / 2.0;
    };
    std::vector<int> open;  // tiles that may still take samples
    for (int i = 0; i < count; ++i) {
        if (tiles[i].samples >= limits.maxSamples) continue;
        if (std::max(tiles[i].estimate.largest, tiles[i].nearbyLargest) > limits.allowedLargest)
            choose(i);
        else
            open.push_back(i);
    }
    // Error removed per sample added: mse / 2 per pixel for samples more per pixel.
    std::stable_sort(open.begin(), open.end(), [&](int a, int b) {
        return tiles[a].estimate.mse() / tiles[a].samples >
               tiles[b].estimate.mse() / tiles[b].samples;
    });
    for (int i : open) {
        if (pixels <= 0.0 || squared / pixels <= limits.allowedMse) break;
        if (tiles[i].estimate.mse() > 0.0) choose(i);
    }
    std::vector<int> refine;
    for (int i = 0; i < count; ++i)
        if (chosen[i]) refine.push_back(i);
    return refine;
}

AdaptiveOutcome adaptiveOutcome(const std::vector<TileSamplingState>& tiles,
                                const AdaptiveSampling& limits, int passes) {
    AdaptiveOutcome o;
    o.tiles = static_cast<int>(tiles.size());
    o.passes = passes;
    if (tiles.empty()) return o;
    double samples = 0.0, pixels = 0.0;
    o.fewestSamples = tiles.front().samples;
    for (const TileSamplingState& t : tiles) {
        samples += double(t.samples) * t.pixels;
        pixels += t.pixels;
        o.fewestSamples = std::min(o.fewestSamples, t.samples);
        o.mostSamples = std::max(o.mostSamples, t.samples);
        o.estimatedLargest = std::max(o.estimatedLargest, t.estimate.largest);
        if (t.samples >= limits.maxSamples &&
            (t.estimate.largest > limits.allowedLargest || t.estimate.mse() > limits.allowedMse))
            ++o.tilesAtCap;
    }
    o.meanSamples = pixels > 0.0 ? samples / pixels : 0.0;
    o.estimatedMse = estimatedPictureMse(tiles);
    return o;
}

}  // namespace whitted
