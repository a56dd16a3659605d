// Checking a quality target against a converged render: what the
// tests on generated scenes assert and what bench_quality prints for
// docs/tradeoff.md, in one place.
#pragma once

#include <cstdint>
#include <vector>

#include "analysis/depth_truncation.h"
#include "analysis/quality_target.h"
#include "image/image.h"
#include "image/image_error.h"
#include "scene/scene.h"
#include "tracer/renderer.h"

namespace whitted {

// The scene in double with `samples` samples a pixel (subPixelSample()'s
// pattern) at `depth`, following no ray that passes on less than
// kReferencePruneWeight of the light: what "converged" means in these checks.
// Only `regions` of the picture, if given (RenderOptions::regions).
Image convergedReference(Scene scene, int samples = 512, int depth = 14,
                         const std::vector<PixelRect>& regions = {});

// A hundredth of what a render to a quality leaves out (kQualityPruneWeight):
// a ray this light changes a pixel near black by about a hundredth of a
// code. Followed whole, a field of glass balls doubles its rays with each
// level, and a reference as deep as kDeepReferenceDepth would never finish.
inline constexpr double kReferencePruneWeight = 1e-6;

// A reference as deep as a plan's check at the picture's size looks: the
// deepest depth SPEC allows, as deep as a plan goes. Where glass keeps rays
// bright, light trapped among the balls of a generated field still changes
// pixels by 100 codes from depth 28 to 32; a reference shallower than a
// plan would judge it against a picture further from the truth than itself.
// On such fields it costs several times depth 14, so the benches use it and
// the tests, whose fields settle sooner, keep 14.
inline constexpr int kDeepReferenceDepth = kMaxDepth;

bool meetsTarget(const ErrorStats& error, const QualityTarget& target);

// A render to a target as whitted-render and the editor make one: the plan,
// then the adaptive render it chose.
struct TargetRender {
    QualityPlan plan;
    RenderResult result;
    double seconds = 0.0;  // on the wall: planning and rendering
    double planSeconds = 0.0;
};

TargetRender renderToTarget(const Scene& scene, const QualityTarget& target);

struct QualityCheck {
    QualityPlan plan;
    Image image;       // the render
    ErrorStats error;  // against the reference
    bool met = false;
    std::uint64_t rays = 0;  // the render's and the plan's probes'
    double seconds = 0.0;    // the same: planning and rendering
    double planSeconds = 0.0;
    double meanSamples = 0.0;
    double estimatedPsnr = 0.0;  // what the plan and the render expected
};

// Plans `scene` for `target`, renders it adaptively and measures it.
QualityCheck checkQuality(const Scene& scene, const QualityTarget& target, const Image& reference);

struct FixedCheck {
    int samples = 0;  // 0: none up to the largest tried met the target
    std::uint64_t rays = 0;
    double seconds = 0.0;
    ErrorStats error;
};

// A fixed render of the scene's own settings, measured.
FixedCheck checkFixed(const Scene& scene, const Image& reference);

// The fewest samples a pixel, a power of two up to maxSamples, meeting the
// target at `depth` with the scene's own pattern and precision; at
// kDeepestChosen where `depth` is deeper. A fixed render follows every ray
// SPEC spawns, and past 16 a field of glass balls doubles them with each
// level (a render to a quality prunes them, kQualityPruneWeight): a fixed
// setting no user would wait for is no setting to compare with.
FixedCheck fewestFixedSamplesMeeting(Scene scene, const QualityTarget& target, int depth,
                                     const Image& reference, int maxSamples = 256);

}  // namespace whitted
