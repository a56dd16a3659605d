// The time model of core/analysis/speed_probe.h: the arithmetic that turns a
// probe's cost a ray into a render's seconds, on hand-made figures; which
// tiles it times; and what a real probe measures of the seed scene. No timing is compared with a
// bound here: the machine's load would decide it (bench_prediction prints the seconds predicted
// against those measured).
#include <cmath>

#include <gtest/gtest.h>

#include "analysis/speed_probe.h"
#include "base/parallel_for.h"
#include "image/image.h"
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

TEST(SpeedProbe, PredictSeconds_CentresAndJitteredRaysAtTheirCostsSharedAmongTheThreads) {
    SpeedProbe probe;
    probe.overheadSeconds = 0.01;
    probe.cost = {2e-8, 5e-8};  // seconds a ray: pixel centres, jittered samples
    // 8 samples a pixel over 8 million rays: all jittered, none a centre;
    // their CPU time shared among the threads (300 tiles: as many as the cores).
    const double threads = resolveThreadCount(0);
    EXPECT_NEAR(predictSeconds(probe, seedAt(640, 480, 8), 8e6), 0.01 + 8e6 * 5e-8 / threads,
                1e-12);
    // One sample a pixel: all centres.
    EXPECT_NEAR(predictSeconds(probe, seedAt(160, 120, 1), 1e6),
                0.01 + 1e6 * 2e-8 / std::min(threads, 20.0), 1e-12);
    // A picture of one 32-pixel tile runs on one thread.
    EXPECT_NEAR(predictSeconds(probe, seedAt(32, 24, 1), 1e6), 0.01 + 1e6 * 2e-8, 1e-12);
}

TEST(SpeedProbe, ProbeTiles_OfALargePicture_AreSmallDisjointAndInEveryPartOfIt) {
    const std::vector<PixelRect> tiles = probeTiles(640, 480, kSpeedProbePixels);
    ASSERT_EQ(tiles.size(), 75u);  // 19,200 pixels in tiles of 16 x 16
    int pixels = 0;
    bool rowBand[4] = {}, columnBand[4] = {};
    for (std::size_t i = 0; i < tiles.size(); ++i) {
        const PixelRect& t = tiles[i];
        EXPECT_TRUE(insidePicture(t, 640, 480));
        EXPECT_EQ(t.width, kSpeedProbeTileSide);
        EXPECT_EQ(t.height, kSpeedProbeTileSide);
        for (std::size_t j = 0; j < i; ++j) EXPECT_FALSE(overlap(t, tiles[j]));
        pixels += t.width * t.height;
        rowBand[t.y * 4 / 480] = columnBand[t.x * 4 / 640] = true;
    }
    EXPECT_EQ(pixels, kSpeedProbePixels);
    for (int band = 0; band < 4; ++band) {
        EXPECT_TRUE(rowBand[band]) << "no tile in the picture's quarter of rows " << band;
        EXPECT_TRUE(columnBand[band]) << "no tile in its quarter of columns " << band;
    }
    // A picture no larger than the pixels asked for is timed whole.
    const std::vector<PixelRect> whole = probeTiles(160, 120, kSpeedProbePixels);
    ASSERT_EQ(whole.size(), 1u);
    EXPECT_EQ(whole[0].width, 160);
    EXPECT_EQ(whole[0].height, 120);
}

TEST(SpeedProbe, ProbeSpeed_OfTheSeed_TimesItsTilesAtThePicturesSize) {
    const SpeedProbe probe = probeSpeed(seedAt(640, 480, 4));
    EXPECT_EQ(probe.pixels, kSpeedProbePixels);
    EXPECT_GT(probe.overheadSeconds, 0.0);
    EXPECT_GT(probe.cost.centre, 0.0);
    EXPECT_GT(probe.cost.jittered, 0.0);
    EXPECT_EQ(probeSpeed(seedAt(100, 75, 4)).pixels, 100 * 75);
}

}  // namespace
}  // namespace whitted
