#include "tracer/adaptive_sampling.h"

namespace whitted {

TileErrorEstimate centreSampleEstimate(const Image& image, const PixelRect& tile) {
    TileErrorEstimate estimate;
    const double scale = std::sqrt(kNeighbourShare);
    // The 8-bit codes the user sees: a table lookup, where srgbCode()'s
    // std::pow would cost more than tracing the centres of a simple scene.
    auto code = [&](int x, int y, int c) { return int(srgbEncode8(image.pixel(x, y)[c])); };
    for (int y = tile.y; y < tile.y + tile.height; ++y)
        for (int x = tile.x; x < tile.x + tile.width; ++x) {
            const bool right = x + 1 < tile.x + tile.width, below = y + 1 < tile.y + tile.height;
            for (int c = 0; c < 3; ++c) {
                const int here = code(x, y, c);
                if (right) estimate.add(scale * (here - code(x + 1, y, c)));
                if (below) estimate.add(scale * (here - code(x, y + 1, c)));
            }
        }
    if (estimate.values == 0) estimate.add(255.0);
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
        if (tiles[i].estimate.largest > limits.allowedLargest)
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
