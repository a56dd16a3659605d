// Rendering to a quality (core/analysis/quality_target.h, issue 15), checked
// where the presets were never fitted: random fields of matte, mirror and
// glass balls (app/field), each against a converged reference (double, 512
// samples a pixel, depth 14). The targets must be met in at least 95% of the
// renders, and Final with no more rays than the fixed sample count that would
// meet it at the same depth (rays, not seconds: a count does not depend on
// the machine's load). Draft and Preview do not get there at this size: Draft
// starts with the pixels' centres, but at 128x96, where balls are a few
// pixels wide, their estimate sends most tiles on to two samples; Preview's
// planning and first two samples cost more than the fixed samples it needs.
// Their ratios are printed, and docs/quality.md has them at 320x240.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "analysis/quality_check.h"
#include "scene/scene_io.h"
#include "sphere_field.h"
#include "tracer/renderer.h"

namespace whitted {
namespace {

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

TEST(QualityTarget, PresetsMeetTheirTargetsOnScenesTheyWereNotFittedOn) {
    const std::vector<QualityTarget> targets = {draftQuality(), previewQuality(), finalQuality()};
    int renders = 0, met = 0, cheaper = 0, compared = 0;
    for (const Scene& scene : generatedScenes()) {
        const Image reference = convergedReference(scene);
        for (const QualityTarget& target : targets) {
            const QualityCheck c = checkQuality(scene, target, reference);
            const FixedCheck fixed =
                fewestFixedSamplesMeeting(scene, target, c.plan.maxDepth, reference);
            ++renders;
            met += c.met;
            if (fixed.samples > 0 && target.name == "Final") {
                ++compared;
                cheaper += c.rays <= fixed.rays;
            }
            std::printf(
                "%zu balls, %-8s depth %2d: %5.1f dB (estimated %5.1f), largest %5.1f "
                "codes, %s; rays %.2fM against %.2fM at %d fixed samples\n",
                scene.spheres.size() - 1, target.name.c_str(), c.plan.maxDepth, c.error.psnrSrgb8,
                c.estimatedPsnr, c.error.largest, c.met ? "met" : "MISSED", c.rays / 1e6,
                fixed.rays / 1e6, fixed.samples);
        }
    }
    EXPECT_GE(met, std::ceil(0.95 * renders)) << met << " of " << renders << " met their target";
    EXPECT_GE(cheaper, std::ceil(0.95 * compared))
        << cheaper << " of " << compared << " Final renders took no more rays than the fixed count";
    EXPECT_GT(compared, 0);
}

// Float against double at the probe's size, depth and samples: the mean
// squared difference of their 8-bit pictures.
double floatAgainstDouble(Scene scene, int samples) {
    scene.render.samplesPerPixel = samples;
    scene.render.precision = Precision::Float;
    const Image inFloat = render(scene, oneShotOptions()).image;
    scene.render.precision = Precision::Double;
    const ErrorStats e = measureError(inFloat, render(scene, oneShotOptions()).image);
    return e.rmseSrgb8 * e.rmseSrgb8;
}

// On glass.json float and double part at pixels' centres in slivers of the
// balls' rims: 0.4 codes^2 against Final's 0.65 at one sample a pixel, under
// a hundredth of that at 256. The plan measures it again with 8 samples a
// pixel and counts what it finds there, no less than what 256 samples show.
TEST(QualityTarget, FloatAgainstDouble_MeasuredWithSamplesWhereTheCentresDifferMuch) {
    Scene glass = loadScene(WHITTED_SCENES_DIR "/glass.json");
    glass.render.width = 320;
    glass.render.height = 240;
    glass.render.precision = Precision::Float;
    const QualityPlan plan = planQuality(glass, finalQuality());
    EXPECT_EQ(plan.precisionSamples, 8);
    EXPECT_NE(plan.why.find("float against double: "), std::string::npos);
    EXPECT_NE(plan.why.find(", at 8 samples a pixel"), std::string::npos) << plan.why;
    Scene probe = glass;
    probe.render.width = plan.probeWidth;
    probe.render.height = plan.probeHeight;
    probe.render.maxDepth = plan.maxDepth;
    const double atCentres = floatAgainstDouble(probe, 1);
    const double atMany = floatAgainstDouble(probe, 256);
    std::printf("float against double: centres %.4f, planned %.4f, 256 samples %.4f codes^2\n",
                atCentres, plan.precisionMse, atMany);
    EXPECT_LT(plan.precisionMse, atCentres / 4.0);
    EXPECT_GE(plan.precisionMse, atMany);
    // A render of one sample a pixel at most shows the centres' difference:
    // that is what its plan counts.
    const QualityPlan oneSample = planQuality(glass, finalQuality(), 1);
    EXPECT_EQ(oneSample.precisionSamples, 1);
    EXPECT_NEAR(oneSample.precisionMse, atCentres, 1e-9);
    // Where the centres' difference is small, it is what the plan counts.
    Scene seed = loadScene(WHITTED_SCENES_DIR "/seed.json");
    seed.render.precision = Precision::Float;
    EXPECT_EQ(planQuality(seed, finalQuality()).precisionSamples, 1);
}

}  // namespace
}  // namespace whitted
