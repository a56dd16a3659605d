// Rendering to a quality (core/analysis/quality_target.h, issue 15), checked
// where the presets were never fitted: random fields of matte, mirror and
// glass balls (app/field), each against a converged reference (double, 512
// samples a pixel, depth 14). The targets must be met in at least 95% of the
// renders, and Final with no more rays than the fixed sample count that would
// meet it at the same depth (rays, not seconds: a count does not depend on
// the machine's load). Draft and Preview do not yet get there (their planning
// and first two samples cost more than the one to eight samples a fixed
// render needs); their ratios are printed, and docs/tradeoff.md has them.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "analysis/quality_target.h"
#include "image/image_error.h"
#include "sphere_field.h"
#include "tracer/renderer.h"

namespace whitted {
namespace {

constexpr int kReferenceSamples = 512;
constexpr int kReferenceDepth = 14;

// Dense fields in front of the camera, 128x96: a few to a few hundred balls,
// a fifth of them glass and a fifth mirrors.
std::vector<Scene> generatedScenes() {
    std::vector<Scene> scenes;
    for (std::uint32_t seed = 1; seed <= 4; ++seed) {
        FieldOptions o;
        o.count = 20 + 60 * int(seed);
        o.seed = 100 + seed;
        o.halfWidth = 2.0 + seed;
        o.depth = 6.0 + 2.0 * seed;
        Scene scene = sphereField(o);
        scene.render.width = 128;
        scene.render.height = 96;
        scenes.push_back(scene);
    }
    return scenes;
}

Image referenceOf(Scene scene) {
    scene.render.precision = Precision::Double;
    scene.render.samplesPerPixel = kReferenceSamples;
    scene.render.maxDepth = kReferenceDepth;
    RenderOptions options;
    options.progressive = false;
    return render(scene, options).image;
}

bool meets(const ErrorStats& e, const QualityTarget& t) {
    return e.psnrSrgb8 >= t.psnrDb && (!t.largestCodes || e.largest <= *t.largestCodes);
}

struct Outcome {
    ErrorStats error;
    std::uint64_t rays = 0;
    QualityPlan plan;
    double estimatedPsnr = 0.0;
};

Outcome renderTo(const Scene& scene, const QualityTarget& target, const Image& reference) {
    Outcome o;
    o.plan = planQuality(scene, target);
    Scene s = scene;
    s.render.maxDepth = o.plan.maxDepth;
    RenderOptions options;
    options.adaptive = o.plan.sampling;
    const RenderResult r = render(s, options);
    o.error = measureError(r.image, reference);
    o.rays = r.rays.total() + o.plan.probeRays;
    o.estimatedPsnr =
        10.0 * std::log10(255.0 * 255.0 /
                          (o.plan.depthMse + o.plan.precisionMse + r.adaptive->estimatedMse));
    return o;
}

// The rays of the fewest fixed samples a pixel (a power of two) meeting the
// target at `depth`; 0 when even 256 do not.
std::uint64_t fixedRaysMeeting(Scene scene, const QualityTarget& target, int depth,
                               const Image& reference) {
    scene.render.maxDepth = depth;
    for (int spp = 1; spp <= 256; spp *= 2) {
        scene.render.samplesPerPixel = spp;
        RenderOptions options;
        options.progressive = false;
        const RenderResult r = render(scene, options);
        if (meets(measureError(r.image, reference), target)) return r.rays.total();
    }
    return 0;
}

TEST(QualityTarget, PresetsMeetTheirTargetsOnScenesTheyWereNotFittedOn) {
    const std::vector<QualityTarget> targets = {draftQuality(), previewQuality(), finalQuality()};
    int renders = 0, met = 0, cheaper = 0, compared = 0;
    for (const Scene& scene : generatedScenes()) {
        const Image reference = referenceOf(scene);
        for (const QualityTarget& target : targets) {
            const Outcome o = renderTo(scene, target, reference);
            const std::uint64_t fixed = fixedRaysMeeting(scene, target, o.plan.maxDepth, reference);
            ++renders;
            met += meets(o.error, target);
            if (fixed > 0 && target.name == "Final") {
                ++compared;
                cheaper += o.rays <= fixed;
            }
            std::printf(
                "%zu balls, %-8s depth %2d: %5.1f dB (estimated %5.1f), largest %5.1f "
                "codes, %s; rays %.2fM against %.2fM fixed\n",
                scene.spheres.size() - 1, target.name.c_str(), o.plan.maxDepth, o.error.psnrSrgb8,
                o.estimatedPsnr, o.error.largest, meets(o.error, target) ? "met" : "MISSED",
                o.rays / 1e6, fixed / 1e6);
        }
    }
    EXPECT_GE(met, std::ceil(0.95 * renders)) << met << " of " << renders << " met their target";
    EXPECT_GE(cheaper, std::ceil(0.95 * compared))
        << cheaper << " of " << compared << " Final renders took no more rays than the fixed count";
    EXPECT_GT(compared, 0);
}

}  // namespace
}  // namespace whitted
