// Predictions for scenes never measured (core/analysis/render_prediction.h),
// checked on random fields of matte, mirror and glass balls that no constant of
// the prediction was fitted on (those come from the shipped scenes): the
// predicted PSNR within 2 dB of what the render then measures against a
// converged one (double, 512 samples, depth 14), the predicted rays within 25%
// of those it traces. Rays, not seconds: a count does not depend on the
// machine's load (bench_prediction prints seconds).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "analysis/quality_check.h"
#include "analysis/render_prediction.h"
#include "sphere_field.h"

namespace whitted {
namespace {

// 240x180: larger than the noise probe, whose 160 pixels then stand for 240.
// One field a test case, so that the three run side by side.
class PredictionOnAField : public testing::TestWithParam<std::uint32_t> {};

TEST_P(PredictionOnAField, PsnrWithinTwoDecibels_RaysWithinAQuarter) {
    const std::uint32_t seed = GetParam();
    const Scene field = sphereField({.count = 40 + 90 * int(seed),
                                     .seed = 200 + seed,
                                     .halfWidth = 2.5 + seed,
                                     .depth = 7.0 + 2.0 * seed},
                                    240, 180);
    const Image reference = convergedReference(field);
    for (const auto& [samples, depth] : {std::pair{1, 2}, {16, 5}, {64, 6}}) {
        Scene scene = field;
        scene.render.samplesPerPixel = samples;
        scene.render.maxDepth = depth;
        const RenderPrediction p = predictRender(scene);
        ASSERT_TRUE(p.predicted) << p.cannot;
        const FixedCheck rendered = checkFixed(scene, reference);
        std::printf(
            "%zu balls, %3d spp, depth %d: predicted %5.1f dB, measured %5.1f dB; "
            "rays %.2f of those traced\n",
            scene.spheres.size() - 1, samples, depth, p.psnrDb, rendered.error.psnrSrgb8,
            p.rays / double(rendered.rays));
        EXPECT_NEAR(p.psnrDb, rendered.error.psnrSrgb8, 2.0)
            << scene.spheres.size() - 1 << " balls, " << samples << " spp, depth " << depth;
        EXPECT_NEAR(p.rays / double(rendered.rays), 1.0, 0.25);
    }
}

INSTANTIATE_TEST_SUITE_P(RenderPrediction, PredictionOnAField, testing::Values(1u, 2u, 3u),
                         [](const testing::TestParamInfo<std::uint32_t>& info) {
                             return "GeneratedField" + std::to_string(info.param);
                         });

TEST(RenderPrediction, PictureSmallerThanAProbe_SaysItCannotRatherThanGuess) {
    const Scene scene = sphereField({}, 64, 48);
    const RenderPrediction p = predictRender(scene);
    EXPECT_FALSE(p.predicted);
    EXPECT_NE(p.cannot.find("smaller than a probe"), std::string::npos) << p.cannot;
}

// The editor stops a prediction whose scene has changed: its probes stop
// as renders do, and nothing is predicted from their empty pictures. Asked
// `stops` times before saying stop: at once, inside the plan, and later.
TEST(RenderPrediction, Stopped_PredictsNothingAndSaysSo) {
    Scene scene = sphereField({.count = 200}, 320, 240);
    scene.render.samplesPerPixel = 16;
    for (const int stops : {0, 40, 400}) {
        int asked = 0;
        const RenderPrediction p = predictRender(scene, [&] { return ++asked > stops; });
        EXPECT_FALSE(p.predicted) << stops;
        EXPECT_EQ(p.cannot, "stopped") << stops;
        EXPECT_GT(asked, stops);
    }
    const QualityPlan plan =
        planQuality(scene, draftQuality(), 1024, std::nullopt, [] { return true; });
    EXPECT_TRUE(plan.stopped);
    EXPECT_FALSE(planQuality(scene, draftQuality()).stopped);
}

}  // namespace
}  // namespace whitted
