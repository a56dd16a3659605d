#include "analysis/quality_check.h"

#include <chrono>
#include <utility>

#include "tracer/renderer.h"

namespace whitted {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

Image convergedReference(Scene scene, int samples, int depth) {
    scene.render.precision = Precision::Double;
    scene.render.samplesPerPixel = samples;
    scene.render.maxDepth = depth;
    return render(scene, oneShotOptions()).image;
}

bool meetsTarget(const ErrorStats& e, const QualityTarget& t) {
    return e.psnrSrgb8 >= t.psnrDb && (!t.largestCodes || e.largest <= *t.largestCodes);
}

QualityCheck checkQuality(const Scene& scene, const QualityTarget& target, const Image& reference) {
    QualityCheck c;
    const auto start = std::chrono::steady_clock::now();
    c.plan = planQuality(scene, target);
    c.planSeconds = secondsSince(start);
    Scene planned = scene;
    RenderOptions options = oneShotOptions();
    applyPlan(c.plan, planned, options);
    RenderResult r = render(planned, options);
    c.seconds = secondsSince(start);
    c.image = std::move(r.image);
    c.error = measureError(c.image, reference);
    c.met = meetsTarget(c.error, target);
    c.rays = r.rays.total() + c.plan.probeRays;
    c.meanSamples = r.adaptive->meanSamples;
    c.estimatedPsnr = estimatedPsnr(c.plan, *r.adaptive);
    return c;
}

FixedCheck checkFixed(const Scene& scene, const Image& reference) {
    const RenderResult r = render(scene, oneShotOptions());
    return {scene.render.samplesPerPixel, r.rays.total(), r.seconds,
            measureError(r.image, reference)};
}

FixedCheck fewestFixedSamplesMeeting(Scene scene, const QualityTarget& target, int depth,
                                     const Image& reference, int maxSamples) {
    scene.render.maxDepth = depth;
    for (int spp = 1; spp <= maxSamples; spp *= 2) {
        scene.render.samplesPerPixel = spp;
        const FixedCheck c = checkFixed(scene, reference);
        if (meetsTarget(c.error, target)) return c;
    }
    return {};
}

}  // namespace whitted
