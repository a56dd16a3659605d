// The time model of core/analysis/speed_probe.h: the arithmetic that carries
// a probe's cost a ray to the picture, on hand-made figures, and what a real
// probe measures of the seed scene. No timing is compared with a bound here:
// the machine's load would decide it (bench_prediction prints the seconds
// predicted against those measured).
#include <cmath>

#include <gtest/gtest.h>

#include "analysis/speed_probe.h"
#include "base/parallel_for.h"
#include "scene/scene_io.h"

namespace whitted {
namespace {

Scene seedAt(int width, int height, int samples) {
    Scene scene = loadScene(WHITTED_SCENES_DIR "/seed.json");
    scene.render.width = width;
    scene.render.height = height;
    scene.render.samplesPerPixel = samples;
    return scene;
}

TEST(SpeedProbe, PredictSeconds_CentresAndJitteredRaysAtTheirCostsScaledToThePicture) {
    SpeedProbe probe;
    probe.overheadSeconds = 0.01;
    probe.side = 160;
    probe.atSide = {2e-8, 5e-8};  // seconds a ray: pixel centres, jittered samples
    probe.sizePower = 0.8;
    // 640 pixels across is two doublings past the probe's side: the first
    // gains 2^-(0.8/2), the second 2^-(0.8/4), each ray costing 2^-0.6 of the probe's.
    // 8 samples a pixel over 8 million rays: all jittered, none a centre;
    // their CPU time shared among the threads (300 tiles: as many as the cores).
    const double threads = resolveThreadCount(0);
    const double seconds = predictSeconds(probe, seedAt(640, 480, 8), 8e6);
    EXPECT_NEAR(seconds, 0.01 + std::pow(2.0, -0.6) * 8e6 * 5e-8 / threads, 1e-12);
    // One sample a pixel: all centres. At the probe's own size: no scaling.
    EXPECT_NEAR(predictSeconds(probe, seedAt(160, 120, 1), 1e6),
                0.01 + 1e6 * 2e-8 / std::min(threads, 20.0), 1e-12);
    // A picture of one 32-pixel tile runs on one thread, each ray at 5^0.8
    // times the probe's cost (a fifth of its side, at the power measured).
    EXPECT_NEAR(predictSeconds(probe, seedAt(32, 24, 1), 1e6),
                0.01 + 1e6 * 2e-8 * std::pow(5.0, 0.8), 1e-12);
}

TEST(SpeedProbe, ProbeSpeed_OfTheSeed_TimesTwoSizesNoLargerThanThePicture) {
    const SpeedProbe probe = probeSpeed(seedAt(640, 480, 4), 160);
    EXPECT_EQ(probe.side, 160);
    EXPECT_GT(probe.overheadSeconds, 0.0);
    EXPECT_GT(probe.atSide.centre, 0.0);
    EXPECT_GT(probe.atSide.jittered, 0.0);
    EXPECT_GT(probe.atHalfSide.centre, 0.0);
    EXPECT_GE(probe.sizePower, 0.0);
    EXPECT_LE(probe.sizePower, 1.0);
    // A picture smaller than the side is timed at its own size.
    EXPECT_EQ(probeSpeed(seedAt(100, 75, 4), 160).side, 100);
}

}  // namespace
}  // namespace whitted
