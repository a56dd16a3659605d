#include "analysis/quality_target.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "analysis/quality_depth.h"
#include "analysis/quality_probes.h"
#include "analysis/quality_why.h"
#include "base/thread_cpu_time.h"
#include "image/image_error.h"

namespace whitted {

namespace {

// A pixel's estimated error is one draw from the same spread as its error,
// so the largest estimate of a tile is about as large as its largest error;
// each halving of the margin costs about four times the samples. 0.8 was
// chosen at 128x96 to 320x240, where tiles of 16 pixels hold so much of the
// picture that most are sampled well past what they need; at the 640x480
// the shipped scenes are saved at, 5 of 6 untuned fields' Previews came out
// 65 to 70 codes off (64 allowed). Under 0.6 all 5 whose plan promised the
// target met it, for about a fifth more time (bench_quality_fields at 640x480;
// docs/design/quality-planning.md).
constexpr double kLargestMargin = 0.6;

// The sampling's share of a target's MSE `total` once the depth and the
// precision have cut off `bias`. While the target can be met the samples get
// what is left, and at least the depth's share. Once the bias alone is over
// the target, chasing it with samples buys a fraction of a dB for several
// times the render (on a dense glass field, 602 samples a pixel instead of
// 108, for 46.2 dB instead of 45.3): the samples are then held to the noise
// of a picture that meets the target.
double samplingMse(double total, double bias) {
    if (bias > total) return kSamplingShare * (1.0 - kDepthShareOfMse) * total;
    return kSamplingShare * std::max(total - bias, kDepthShareOfMse * total);
}

}  // namespace

QualityTarget draftQuality() {
    return {"Draft", 20.0, std::nullopt};
}
QualityTarget previewQuality() {
    return {"Preview", 35.0, 64.0};
}
QualityTarget finalQuality() {
    return {"Final", 50.0, 16.0};
}

std::optional<QualityTarget> qualityPreset(std::string_view name) {
    std::string lower(name);
    for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (lower == "draft") return draftQuality();
    if (lower == "preview") return previewQuality();
    if (lower == "final") return finalQuality();
    return std::nullopt;
}

double allowedMse(double psnrDb) {
    return 255.0 * 255.0 / std::pow(10.0, psnrDb / 10.0);
}

void applyPlan(const QualityPlan& plan, Scene& scene, RenderOptions& options) {
    scene.render.maxDepth = plan.maxDepth;
    options.adaptive = plan.sampling;
    options.pruneBelowWeight = kQualityPruneWeight;
}

double estimatedPsnr(const QualityPlan& plan, const AdaptiveOutcome& outcome) {
    return psnrFromMse(plan.depthMse + plan.precisionMse + outcome.estimatedMse);
}

bool plannedAlike(const Scene& a, const Scene& b) {
    return a.render.width == b.render.width && a.render.height == b.render.height &&
           a.render.precision == b.render.precision && sameSceneContent(a, b);
}

QualityPlan planQuality(const Scene& scene, const QualityTarget& target, int maxSamples,
                        std::optional<int> depth, const StopPredicate& stop) {
    const double start = threadCpuSeconds();
    QualityPlan plan;
    plan.target = target;
    // A stopped probe is an empty picture: the depth search then ends at
    // once, and the plan is marked as stopped below.
    planning::ProbeRenders probes(scene, target.psnrDb, stop);
    planning::planDepth(probes, depth, maxSamples, plan);
    planning::checkDepthAtPictureSize(probes, maxSamples, plan);
    plan.sampling.maxSamples = std::max(1, maxSamples);
    plan.sampling.centresFirst = !target.largestCodes && target.psnrDb <= kCentresFirstUpToDb;
    planning::planPrecision(probes, plan);
    plan.stopped = stop && stop();
    const double total = allowedMse(target.psnrDb);
    const double bias = plan.depthMse + plan.precisionMse;
    plan.sampling.allowedMse = samplingMse(total, bias);
    // The largest errors of the depth and of the sampling are seldom in the
    // same pixel (light trapped in glass; edges), so each gets the whole limit.
    if (target.largestCodes) plan.sampling.allowedLargest = kLargestMargin * *target.largestCodes;
    plan.why = planning::planWhy(plan, scene.render.precision == Precision::Float, total);
    plan.cpuSeconds = threadCpuSeconds() - start;
    return plan;
}

}  // namespace whitted
