#include "analysis/target_prediction.h"

#include <chrono>

#include "analysis/speed_probe.h"
#include "base/thread_cpu_time.h"
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

double pixelsOf(const std::vector<PixelRect>& rects) {
    double pixels = 0.0;
    for (const PixelRect& r : rects) pixels += double(r.width) * r.height;
    return pixels;
}

}  // namespace

TargetPrediction predictRenderTo(const Scene& scene, const QualityTarget& target, int maxSamples,
                                 const StopPredicate& stop) {
    const auto start = std::chrono::steady_clock::now();
    TargetPrediction p;
    const double picture = double(scene.render.width) * scene.render.height;
    if (picture <= kSpeedProbePixels)
        return notPredicted(p, "a picture this small is rendered as fast as it is predicted");
    const double planStart = threadCpuSeconds();
    p.plan = planQuality(scene, target, maxSamples, std::nullopt, stop);
    p.planSeconds = threadCpuSeconds() - planStart;
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
    const double scale = 1.0 / p.tilesShare;
    p.meanSamples = tiles.adaptive->meanSamples;
    p.psnrDb = estimatedPsnr(p.plan, *tiles.adaptive);
    p.largestCodes = tiles.adaptive->estimatedLargest;
    p.renderRays = double(tiles.rays.total()) * scale;
    p.renderSeconds = overhead + tiles.tilesCpuSeconds * scale / threads;
    p.probeRays = p.plan.probeRays + tiles.rays.total();
    p.probeSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    p.predicted = true;
    return p;
}

}  // namespace whitted
