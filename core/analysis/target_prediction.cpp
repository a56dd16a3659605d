#include "analysis/target_prediction.h"

#include <chrono>

#include "analysis/speed_probe.h"
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

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
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
    const RenderResult tiles = render(planned, options, {}, stop);
    if (!tiles.completed || !tiles.adaptive) return notPredicted(p, "stopped");

    p.tilesShare = pixelsOf(options.regions) / picture;
    p.probeRays = p.plan.probeRays + tiles.rays.total();
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
