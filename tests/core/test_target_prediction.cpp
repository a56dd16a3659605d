// Predictions of a render to a target (core/analysis/target_prediction.h) on
// random fields of matte, mirror and glass balls that nothing was fitted on:
// the plan the render then makes, and its samples, estimate and rays, from a
// quarter of the picture's tiles. Rays, not seconds: a count does not depend on
// the machine's load (bench_prediction --targets prints the seconds).
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "analysis/quality_check.h"
#include "analysis/target_prediction.h"
#include "sphere_field.h"

namespace whitted {
namespace {

// 240x180: 169 tiles of the adaptive render, of which the prediction renders 75.
Scene generatedField(std::uint32_t seed) {
    return sphereField({.count = 40 + 90 * int(seed),
                        .seed = 300 + seed,
                        .halfWidth = 2.5 + seed,
                        .depth = 7.0 + 2.0 * seed},
                       240, 180);
}

TEST(TargetPrediction, GeneratedFields_SamplesRaysAndEstimateOfTheRenderItPredicts) {
    for (std::uint32_t seed = 1; seed <= 3; ++seed) {
        const Scene scene = generatedField(seed);
        for (const QualityTarget& target : {draftQuality(), previewQuality()}) {
            const TargetPrediction p = predictRenderTo(scene, target);
            ASSERT_TRUE(p.predicted) << p.cannot;
            const TargetRender r = renderToTarget(scene, target);
            const AdaptiveOutcome& reached = *r.result.adaptive;
            const double rendered = estimatedPsnr(r.plan, reached);
            const double rays = p.rays() / double(r.plan.probeRays + r.result.rays.total());
            std::printf(
                "%zu balls, %s: depth %d, %.1f of %.1f samples a pixel, %.1f dB of %.1f "
                "estimated, rays %.2f of those traced\n",
                scene.spheres.size() - 1, target.name.c_str(), p.plan.maxDepth, p.meanSamples,
                reached.meanSamples, p.psnrDb, rendered, rays);
            EXPECT_EQ(p.plan.maxDepth, r.plan.maxDepth);
            EXPECT_EQ(p.plan.why, r.plan.why);
            EXPECT_NEAR(p.meanSamples / reached.meanSamples, 1.0, 0.25);
            EXPECT_NEAR(p.psnrDb, rendered, 2.0);
            // Within 25%, and closer: scaled by the pixels' ratio the
            // tiles' rays were 0.86 to 1.09 of the render's, by the coarse
            // picture's rays 1.01 to 1.07. Since the render looks past a
            // tile's border (unseenLargest(), estimateNearbyLargest()), the
            // tiles rendered alone were 0.81 to 1.08: the second field's
            // Preview spends its extra samples on the rims of its balls,
            // where rays are dear. With the scene around them rendered too
            // (AroundRegions), 0.95 to 1.07.
            EXPECT_NEAR(rays, 1.0, 0.15);
            EXPECT_GT(p.seconds(), p.planSeconds);
        }
    }
}

TEST(TargetPrediction, PictureNoLargerThanItsTiles_SaysItCannotRatherThanGuess) {
    Scene scene = generatedField(1);
    scene.render.width = 160;
    scene.render.height = 120;
    const TargetPrediction p = predictRenderTo(scene, previewQuality());
    EXPECT_FALSE(p.predicted);
    EXPECT_EQ(p.cannot, "a picture this small is rendered as fast as it is predicted");
    EXPECT_EQ(p.probeRays, 0u);
}

TEST(TargetPrediction, Stopped_PredictsNothingAndSaysSo) {
    const Scene scene = generatedField(2);
    for (const int stops : {0, 40, 4000}) {
        int asked = 0;
        const TargetPrediction p = predictRenderTo(scene, previewQuality(), kDefaultMaxSamples,
                                                   [&] { return ++asked > stops; });
        EXPECT_FALSE(p.predicted) << stops;
        EXPECT_EQ(p.cannot, "stopped") << stops;
        EXPECT_GT(asked, stops);
    }
}

}  // namespace
}  // namespace whitted
