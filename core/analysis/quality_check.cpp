#include "analysis/quality_check.h"

#include <algorithm>
#include <chrono>
#include <utility>

#include "base/elapsed.h"

namespace whitted {

Image convergedReference(Scene scene, int samples, int depth,
                         const std::vector<PixelRect>& regions) {
    scene.render.precision = Precision::Double;
    scene.render.samplesPerPixel = samples;
    scene.render.maxDepth = depth;
    RenderOptions options = oneShotOptions();
    options.pruneBelowWeight = kReferencePruneWeight;
    options.regions = regions;
    return render(scene, options).image;
}

bool meetsTarget(const ErrorStats& e, const QualityTarget& t) {
    return e.psnrSrgb8 >= t.psnrDb && (!t.largestCodes || e.largest <= *t.largestCodes);
}

TargetRender renderToTarget(const Scene& scene, const QualityTarget& target) {
    TargetRender r;
    const auto start = std::chrono::steady_clock::now();
    r.plan = planQuality(scene, target);
    r.planSeconds = secondsSince(start);
    Scene planned = scene;
    RenderOptions options = oneShotOptions();
    applyPlan(r.plan, planned, options);
    r.result = render(planned, options);
    r.seconds = secondsSince(start);
    return r;
}

QualityCheck checkQuality(const Scene& scene, const QualityTarget& target, const Image& reference) {
    TargetRender r = renderToTarget(scene, target);
    QualityCheck c;
    c.plan = std::move(r.plan);
    c.planSeconds = r.planSeconds;
    c.seconds = r.seconds;
    c.image = std::move(r.result.image);
    c.error = measureError(c.image, reference);
    c.met = meetsTarget(c.error, target);
    c.rays = r.result.rays.total() + c.plan.probeRays;
    c.meanSamples = r.result.adaptive->meanSamples;
    c.estimatedPsnr = estimatedPsnr(c.plan, *r.result.adaptive);
    return c;
}

FixedCheck checkFixed(const Scene& scene, const Image& reference) {
    const RenderResult r = render(scene, oneShotOptions());
    return {scene.render.samplesPerPixel, r.rays.total(), r.seconds,
            measureError(r.image, reference)};
}

FixedCheck fewestFixedSamplesMeeting(Scene scene, const QualityTarget& target, int depth,
                                     const Image& reference, int maxSamples) {
    scene.render.maxDepth = std::min(depth, kDeepestChosen);
    for (int spp = 1; spp <= maxSamples; spp *= 2) {
        scene.render.samplesPerPixel = spp;
        const FixedCheck c = checkFixed(scene, reference);
        if (meetsTarget(c.error, target)) return c;
    }
    return {};
}

}  // namespace whitted
