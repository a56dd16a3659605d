#include "analysis/target_prediction.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <mutex>
#include <optional>

#include "analysis/speed_probe.h"
#include "base/elapsed.h"
#include "tracer/adaptive_sampling.h"

namespace whitted {

// The probe's tiles must be whole tiles of the adaptive render: a tile cut
// in two would be sampled as two smaller ones.
static_assert(kSpeedProbeTileSide == kAdaptiveTileEdge);

namespace {

TargetPrediction notPredicted(TargetPrediction p, std::string why) {
    p.predicted = false;
    p.cannot = std::move(why);
    return p;
}

constexpr const char* kTooSmall = "a picture this small is rendered as fast as it is predicted";

bool tooSmallToPredict(const Scene& scene) {
    return double(scene.render.width) * scene.render.height <= kSpeedProbePixels;
}

double pixelsOf(const std::vector<PixelRect>& rects) {
    double pixels = 0.0;
    for (const PixelRect& r : rects) pixels += double(r.width) * r.height;
    return pixels;
}

// The picture's rays over the tiles' at one centre a pixel, at the plan's
// depth, in a picture a quarter as wide and high or coarser (its pixels at
// most kCoarsePixels): by how much to scale the tiles' rays and time up to
// the picture's. Glass can trap light in a few tiles, and 75 tiles drawn
// over a quarter of a picture took 1.4 times their share of the rays of a
// 150-ball field; a coarse picture costs a sixteenth of a sample a pixel and
// sees where those tiles are. Falls back on the pixels' ratio.
constexpr int kCoarsePixels = 4 * kSpeedProbePixels;

double tilesToPicture(const Scene& planned, const std::vector<PixelRect>& tiles, double pixelsRatio,
                      std::uint64_t& rays, const StopPredicate& stop) {
    const double pixels = double(planned.render.width) * planned.render.height;
    int factor = 4;  // divides the tiles' side and corners, multiples of 16
    while (factor < kSpeedProbeTileSide && pixels / (factor * factor) > kCoarsePixels) factor *= 2;
    auto coarse = [&](int size) { return (size + factor - 1) / factor; };
    Scene scene = planned;
    scene.render.width = coarse(planned.render.width);
    scene.render.height = coarse(planned.render.height);
    scene.render.samplesPerPixel = 1;
    RenderOptions options = oneShotOptions();
    options.sceneValidated = true;
    options.pruneBelowWeight = kQualityPruneWeight;  // as the render to the plan (applyPlan())
    const RenderResult picture = render(scene, options, {}, stop);
    for (const PixelRect& t : tiles)
        options.regions.push_back({t.x / factor, t.y / factor, coarse(t.width), coarse(t.height)});
    const RenderResult under = render(scene, options, {}, stop);
    rays += picture.rays.total() + under.rays.total();
    if (!picture.completed || !under.completed || under.rays.total() == 0) return pixelsRatio;
    return double(picture.rays.total()) / double(under.rays.total());
}

// The pixels within `reach` around `tiles` and inside the picture, as
// rectangles: a render's regions may not overlap, and two tiles may share
// pixels of their rings. Runs along rows, those of the rows below that
// match joined to them.
std::vector<PixelRect> ringAround(const std::vector<PixelRect>& tiles, int reach, int width,
                                  int height) {
    std::vector<char> inRing(std::size_t(width) * height, 0);
    for (const PixelRect& t : tiles)
        for (int y = std::max(0, t.y - reach); y < std::min(height, t.y + t.height + reach); ++y)
            for (int x = std::max(0, t.x - reach); x < std::min(width, t.x + t.width + reach); ++x)
                if (!contains(t, x, y)) inRing[std::size_t(y) * width + x] = 1;
    std::vector<PixelRect> rects;
    std::vector<std::size_t> open;  // rects that the last row's runs ended
    for (int y = 0; y < height; ++y) {
        std::vector<std::size_t> ended;
        for (int x = 0; x < width; ++x) {
            const int start = x;
            while (x < width && inRing[std::size_t(y) * width + x]) ++x;
            if (x == start) continue;
            auto above = std::find_if(open.begin(), open.end(), [&](std::size_t i) {
                return rects[i].x == start && rects[i].width == x - start;
            });
            if (above != open.end()) {
                ++rects[*above].height;
                ended.push_back(*above);
            } else {
                ended.push_back(rects.size());
                rects.push_back({start, y, x - start, 1});
            }
        }
        open = std::move(ended);
    }
    return rects;
}

// The scene around `tiles` for the estimates that look past a tile's border
// (RenderOptions::aroundRegions): each pixel's colour, and its halves'
// estimate of its largest error. Each tile's ring at the samples the tile
// took rendered alone (`samplesOf`), which stand for its neighbours' in the
// whole render: a neighbour's estimate is carried to a tile's samples by
// their square root, which overstates it where the two differ much (with
// every ring at 16, field.json's Final at 640x480 was predicted at 1.7 times
// its rays). None if stopped.
std::optional<AroundRegions> aroundTiles(const Scene& planned,
                                         const std::map<int, std::vector<PixelRect>>& samplesOf,
                                         std::uint64_t& rays, const StopPredicate& stop) {
    const int width = planned.render.width, height = planned.render.height;
    AroundRegions around{Image(width, height), PixelLargest{}, 1};  // carried to one sample
    around.largest.width = width, around.largest.height = height;
    around.largest.codes.resize(std::size_t(width) * height);
    RenderOptions options = oneShotOptions();
    options.sceneValidated = true;
    options.pruneBelowWeight = kQualityPruneWeight;  // as the render to the plan (applyPlan())
    for (const auto& [samples, tiles] : samplesOf) {
        options.regions = ringAround(tiles, kNearbyReach, width, height);
        // No limit met before `samples`: every tile is sampled up to them.
        options.adaptive =
            AdaptiveSampling{.allowedMse = 0.0, .allowedLargest = 0.0, .maxSamples = samples};
        const RenderResult ring = render(planned, options, {}, stop);
        rays += ring.rays.total();
        if (!ring.completed) return std::nullopt;
        const float toOneSample = std::sqrt(float(samples));
        for (const PixelRect& r : options.regions)
            for (int y = r.y; y < r.y + r.height; ++y)
                for (int x = r.x; x < r.x + r.width; ++x) {
                    std::copy_n(ring.image.pixel(x, y), 3, around.image.pixel(x, y));
                    around.largest.at(x, y) = ring.pixelLargest.at(x, y) * toOneSample;
                }
    }
    return around;
}

// The tiles of a render, by the samples each took.
struct SamplesOfTiles {
    std::mutex lock;
    std::map<std::pair<int, int>, int> byCorner;
    void note(const TileUpdate& t) {
        std::lock_guard<std::mutex> hold(lock);
        int& samples = byCorner[{t.x, t.y}];
        samples = std::max(samples, t.progress.samples);
    }
    std::map<int, std::vector<PixelRect>> of(const std::vector<PixelRect>& tiles) {
        std::map<int, std::vector<PixelRect>> grouped;
        for (const PixelRect& t : tiles) grouped[std::max(1, byCorner[{t.x, t.y}])].push_back(t);
        return grouped;
    }
};

}  // namespace

TargetPrediction predictRenderTo(const Scene& scene, const QualityTarget& target, int maxSamples,
                                 const StopPredicate& stop) {
    if (tooSmallToPredict(scene)) return notPredicted({}, kTooSmall);
    const auto start = std::chrono::steady_clock::now();
    const QualityPlan plan = planQuality(scene, target, maxSamples, std::nullopt, stop);
    const double planning = secondsSince(start);
    TargetPrediction p = predictRenderTo(scene, plan, stop);
    p.probeSeconds += planning;
    return p;
}

TargetPrediction predictRenderTo(const Scene& scene, const QualityPlan& plan,
                                 const StopPredicate& stop) {
    const auto start = std::chrono::steady_clock::now();
    TargetPrediction p;
    if (tooSmallToPredict(scene)) return notPredicted(p, kTooSmall);
    const double picture = double(scene.render.width) * scene.render.height;
    p.plan = plan;
    p.planSeconds = plan.cpuSeconds;
    if (p.plan.stopped) return notPredicted(p, "stopped");

    Scene planned = scene;
    RenderOptions options = oneShotOptions();
    applyPlan(p.plan, planned, options);
    const int threads = renderThreads(planned.render, options);  // the whole picture's
    options.regions = probeTiles(scene.render.width, scene.render.height, kSpeedProbePixels);
    options.sceneValidated = true;  // planning rendered it
    const double overhead = renderOverheadSeconds(planned, stop);
    p.probeRays = p.plan.probeRays;
    SamplesOfTiles alone;
    RenderResult tiles = render(
        planned, options, [&](const TileUpdate& t) { alone.note(t); }, stop);
    std::optional<AroundRegions> around;
    // Only the estimates of the largest error look past a tile. Rendered
    // alone, a field's tiles at 640x480 took 0.7 of the render's rays.
    if (limitsLargest(p.plan.sampling) && tiles.completed && tiles.adaptive) {
        p.probeRays += tiles.rays.total();
        around = aroundTiles(planned, alone.of(options.regions), p.probeRays, stop);
        if (!around) return notPredicted(p, "stopped");
        options.aroundRegions = &*around;
        tiles = render(planned, options, {}, stop);
    }
    if (!tiles.completed || !tiles.adaptive) return notPredicted(p, "stopped");

    p.tilesShare = pixelsOf(options.regions) / picture;
    p.probeRays += tiles.rays.total();
    const double scale =
        tilesToPicture(planned, options.regions, 1.0 / p.tilesShare, p.probeRays, stop);
    if (stop && stop()) return notPredicted(p, "stopped");
    p.meanSamples = tiles.adaptive->meanSamples;
    p.psnrDb = estimatedPsnr(p.plan, *tiles.adaptive);
    p.largestCodes = tiles.adaptive->estimatedLargest;
    p.renderRays = double(tiles.rays.total()) * scale;
    p.renderSeconds = overhead + tiles.tilesCpuSeconds * scale / threads;
    p.probeSeconds = secondsSince(start);
    p.predicted = true;
    return p;
}

}  // namespace whitted
