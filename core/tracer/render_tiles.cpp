#include "tracer/render_tiles.h"

#include <algorithm>

#include "tracer/whitted1980_sampling.h"

namespace whitted {

// Centre-out order: the middle of the image, where people look, arrives first.
std::vector<Tile> spiralTiles(int width, int height, int size) {
    std::vector<Tile> tiles;
    for (int y = 0; y < height; y += size)
        for (int x = 0; x < width; x += size)
            tiles.push_back({x, y, std::min(size, width - x), std::min(size, height - y)});
    auto distance = [&](const Tile& t) {
        const double dx = t.x + t.w * 0.5 - width * 0.5, dy = t.y + t.h * 0.5 - height * 0.5;
        return dx * dx + dy * dy;
    };
    std::stable_sort(tiles.begin(), tiles.end(),
                     [&](const Tile& a, const Tile& b) { return distance(a) < distance(b); });
    return tiles;
}

namespace {

// The tiles of the regions, clipped to each: the same tiles as the whole
// image's where they lie inside one.
std::vector<Tile> regionTiles(const std::vector<Tile>& tiles,
                              const std::vector<PixelRect>& regions) {
    std::vector<Tile> clipped;
    for (const Tile& t : tiles)
        for (const PixelRect& r : regions) {
            const int x0 = std::max(t.x, r.x), x1 = std::min(t.x + t.w, r.x + r.width);
            const int y0 = std::max(t.y, r.y), y1 = std::min(t.y + t.h, r.y + r.height);
            if (x0 < x1 && y0 < y1) clipped.push_back({x0, y0, x1 - x0, y1 - y0});
        }
    return clipped;
}

// RenderOptions::alsoAtDepths that the render cannot give, in words.
std::optional<std::string> alsoAtDepthsProblem(const RenderSettings& r, const RenderOptions& o) {
    const std::vector<int>& d = o.alsoAtDepths;
    if (d.empty()) return std::nullopt;
    if (o.adaptive || o.progressive) return "alsoAtDepths: only for a one-shot render";
    if (d.front() < 0 || d.back() >= r.maxDepth || !std::is_sorted(d.begin(), d.end()))
        return "alsoAtDepths: depths ascending, from 0 to below max_depth " +
               std::to_string(r.maxDepth);
    return std::nullopt;
}

// Why the regions cannot be rendered, if they cannot: one outside the
// picture, or two that overlap (their tiles would be rendered twice, by two
// threads at once).
std::optional<std::string> regionsProblem(const std::vector<PixelRect>& regions, int width,
                                          int height) {
    for (std::size_t i = 0; i < regions.size(); ++i) {
        if (!insidePicture(regions[i], width, height))
            return "the region " + cornersText(regions[i]) + " is not a part of the " +
                   std::to_string(width) + "x" + std::to_string(height) + " image";
        for (std::size_t j = 0; j < i; ++j)
            if (overlap(regions[i], regions[j]))
                return "the regions " + cornersText(regions[j]) + " and " +
                       cornersText(regions[i]) + " overlap";
    }
    return std::nullopt;
}

std::optional<std::string> whitted1980Problem(const RenderOptions& o) {
    if (!o.whitted1980) return std::nullopt;
    if (o.adaptive || !o.regions.empty() || !o.alsoAtDepths.empty())
        return "Whitted's 1980 sampling renders the whole picture, with no target and no "
               "regions or other depths";
    if (o.whitted1980->maxLevels < 0 || o.whitted1980->maxLevels > kMaxWhitted1980Levels)
        return "Whitted's 1980 sampling cuts a pixel 0 to " +
               std::to_string(kMaxWhitted1980Levels) + " times";
    if (!(o.whitted1980->threshold >= 0))
        return "Whitted's 1980 sampling needs a threshold of 0 or more";
    return std::nullopt;
}

}  // namespace

// The tile edge: an adaptive render's own (adaptive_sampling.h), else as asked.
int tileEdgeOf(const RenderOptions& o) {
    return std::max(1, o.adaptive ? kAdaptiveTileEdge : o.tileSize);
}

// The preview's block edge: a divisor of the tile edge, so that tiles hold
// whole blocks and no block is traced twice.
int previewBlockOf(const RenderOptions& o) {
    const int tile = tileEdgeOf(o);
    int block = std::clamp(o.previewBlock, 1, tile);
    while (tile % block != 0) --block;
    return block;
}

// The tiles a render works through, in the order it takes them.
std::vector<Tile> renderTiles(const RenderSettings& r, const RenderOptions& o) {
    std::vector<Tile> tiles = spiralTiles(r.width, r.height, tileEdgeOf(o));
    return o.regions.empty() ? tiles : regionTiles(tiles, o.regions);
}

// The threads a render of `tiles` tiles runs on: as asked, no more than its tiles.
int threadsForTiles(const RenderOptions& o, std::size_t tiles) {
    return std::max(1, std::min<int>(resolveThreadCount(o.threads), tiles));
}

double pixelsRendered(const RenderSettings& r, const RenderOptions& o) {
    if (o.regions.empty()) return double(r.width) * r.height;
    double pixels = 0.0;
    for (const PixelRect& g : o.regions) pixels += double(g.width) * g.height;
    return pixels;
}

std::vector<RenderPass> planPasses(const RenderSettings& r, const RenderOptions& o) {
    const double pixels = pixelsRendered(r, o);
    std::vector<RenderPass> passes;
    const int spp = r.samplesPerPixel;
    if (!o.progressive || !o.regions.empty()) {
        passes.push_back({PassKind::Samples, 0, spp, pixels * spp});
        return passes;
    }
    const int block = previewBlockOf(o);
    if (block > 1 && (r.width > block || r.height > block))
        passes.push_back({PassKind::Preview, 0, 0, pixels / (double(block) * block)});
    for (int done = 0; done < spp;) {
        const int next = done == 0 ? 1 : std::min(spp, done * 2);
        passes.push_back({PassKind::Samples, done, next, pixels * (next - done)});
        done = next;
    }
    return passes;
}

std::optional<std::string> optionsProblem(const Scene& scene, const RenderOptions& options) {
    if (auto problem = regionsProblem(options.regions, scene.render.width, scene.render.height))
        return problem;
    if (auto problem = alsoAtDepthsProblem(scene.render, options)) return problem;
    if (auto problem = whitted1980Problem(options)) return problem;
    const AroundRegions* around = options.aroundRegions;
    if (around &&
        (around->image.width != scene.render.width || around->image.height != scene.render.height ||
         around->largest.width != scene.render.width ||
         around->largest.height != scene.render.height))
        return "the picture around the regions is not the render's size";
    return std::nullopt;
}

}  // namespace whitted
