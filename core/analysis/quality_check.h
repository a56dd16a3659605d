// Checking a quality target against a converged render (issue 15): what the
// tests on generated scenes assert and what bench_quality prints for
// docs/tradeoff.md, in one place.
#pragma once

#include <cstdint>

#include "analysis/depth_truncation.h"
#include "analysis/quality_target.h"
#include "image/image.h"
#include "image/image_error.h"
#include "scene/scene.h"
#include "tracer/renderer.h"

namespace whitted {

// The scene in double with `samples` samples a pixel (subPixelSample()'s
// pattern) at `depth`: what "converged" means in these checks.
Image convergedReference(Scene scene, int samples = 512, int depth = 14);

// A reference as deep as a plan's check at the picture's size looks: three
// levels past the deepest depth a plan chooses. Where glass keeps rays
// bright, depth 14 is not converged (bench_quality_fields' seventeenth field
// has a pixel 80 codes brighter at 17), and a plan at 16 would be judged
// against a picture further from the truth than itself. On such fields it
// costs two to ten times depth 14, so the benches use it and the tests,
// whose fields settle sooner, keep 14.
inline constexpr int kDeepReferenceDepth = kDeepestChosen + 3;

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
// target at `depth` with the scene's own pattern and precision.
FixedCheck fewestFixedSamplesMeeting(Scene scene, const QualityTarget& target, int depth,
                                     const Image& reference, int maxSamples = 256);

}  // namespace whitted
