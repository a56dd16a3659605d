// Without the sphere tree, a packet of camera rays tests only the spheres
// whose screen box it meets (screen_boxes.h), and a shadow ray only those
// whose cone from the light holds its direction (shadow_cones.h). Skipping the
// others must change no pixel: rows traced so equal rows traced testing every
// sphere, bit for bit, from random cameras and lights among random spheres and
// a huge floor, in both precisions and under every kernel. Seed printed on
// failure.
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/core_support.h"
#include "tracer/screen_boxes.h"
#include "tracer/shadow_cones.h"
#include "tracer/tracer.h"

namespace whitted {
namespace {

Scene randomScene(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> pos(-4.0, 4.0), logR(-3.0, 0.5), unit(0.0, 1.0);
    Scene scene;
    scene.render.width = 40;
    scene.render.height = 30;
    scene.render.maxDepth = 2;
    scene.render.samplesPerPixel = 3;
    scene.materials = {Material{"m", {0.5, 0.2, 0.1}, 1, 50, 0.5, 0, 1.5, Checker{{0, 0, 0}, 0.5}},
                       Material{"glass", {0, 0, 0}, 1, 200, 0.1, 0.9, 1.5, std::nullopt}};
    scene.lights = {Light{"key", {5, 5, -10}, {1, 1, 1}, 1},
                    Light{"fill", {pos(rng), pos(rng), pos(rng)}, {0.5, 0.5, 0.5}, 1}};
    scene.spheres = {Sphere{"floor", {0, -99999.5, 0}, 99999, "m"}};
    for (int k = 0; k < 6; ++k)
        scene.spheres.push_back(Sphere{"s" + std::to_string(k),
                                       {pos(rng), pos(rng), pos(rng)},
                                       std::pow(10.0, logR(rng)),
                                       k % 2 ? "glass" : "m"});
    // The eye sometimes inside a ball, sometimes just above the floor.
    Vec3 eye{pos(rng), unit(rng) < 0.3 ? -0.5 + 1e-3 * unit(rng) : pos(rng) * 0.5, pos(rng)};
    if (unit(rng) < 0.2) eye = scene.spheres[1].center;
    if (unit(rng) < 0.2) scene.lights[1].position = scene.spheres[2].center;
    Vec3 ahead{pos(rng), pos(rng) * 0.3, pos(rng)};
    if (glm::length(ahead - eye) < 0.1) ahead += Vec3(1.0);
    scene.camera = Camera{eye, ahead, {0, 1, 0}, 20.0 + 150.0 * unit(rng)};
    return scene;
}

// Rows of every sample with the scene's boxes and cones and without: equal
// bit for bit. Returns how many (row, sphere) pairs the boxes let the rows skip.
template <typename T>
int checkSkipsChangeNoPixel(const Scene& scene, unsigned seed) {
    const PreparedScene<T> boxed = prepareScene<T>(scene);
    PreparedScene<T> every = boxed;
    every.screenBoxes.clear();
    for (PreparedLight<T>& light : every.lights) light.cones.clear();
    test::expectSameRows(boxed, every, scene, "seed " + std::to_string(seed));
    const float w = float(scene.render.width);
    int skipped = 0;
    for (int y = 0; y < scene.render.height; ++y) {
        const std::uint32_t seen =
            spheresInView(boxed.screenBoxes, 0.0f, w, float(y), float(y + 1));
        skipped += int(boxed.screenBoxes.size()) - __builtin_popcount(seen);
    }
    return skipped;
}

TEST(SkippedSpheres, ChangeNoPixel) {
    test::forEveryKernel([](const std::string&) {
        int skipped = 0, pairs = 0;
        for (unsigned seed = 1; seed <= 40; ++seed) {
            const Scene scene = randomScene(seed);
            skipped += checkSkipsChangeNoPixel<float>(scene, seed);
            skipped += checkSkipsChangeNoPixel<double>(scene, seed);
            pairs += 2 * scene.render.height * int(scene.spheres.size());
        }
        // The boxes do leave spheres out, or this test would test nothing.
        EXPECT_GT(skipped, pairs / 3);
    });
}

// The seed's sky, the picture's top row, meets no sphere's box, and the
// bottom row only the floor's; from the key light each ball fills a cone
// 0.03 to 0.05 radians wide, the floor nearly a half-space.
TEST(SkippedSpheres, SeedSkyTestsNoSphereAndEachBallShadowsANarrowCone) {
    Scene scene;
    scene.camera = Camera{{0, 0.35, -1}, {0, 0.25, 0}, {0, 1, 0}, 73.74};
    scene.render.width = 640;
    scene.render.height = 480;
    scene.materials = {Material{"m", {0.5, 0.5, 0.5}, 1, 50, 0.5, 0, 1.5, std::nullopt}};
    scene.lights = {Light{"key", {5, 5, -10}, {1, 1, 1}, 1}};
    scene.spheres = {Sphere{"blue", {1, 0.2, 2}, 0.6, "m"},
                     Sphere{"purple", {-0.95, 0.31, 1.25}, 0.6, "m"},
                     Sphere{"white", {-0.175, 0.51, 7.5}, 0.6, "m"},
                     Sphere{"floor", {0, -99999.5, 0}, 99999, "m"}};
    const PreparedScene<float> s = prepareScene<float>(scene);
    ASSERT_EQ(s.screenBoxes.size(), 4u);
    EXPECT_EQ(spheresInView(s.screenBoxes, 0.0f, 640.0f, 0.0f, 1.0f), 0u);
    EXPECT_EQ(spheresInView(s.screenBoxes, 0.0f, 640.0f, 479.0f, 480.0f), 1u << 3);
    const std::vector<ShadowCone<float>>& cones = s.lights.at(0).cones;
    ASSERT_EQ(cones.size(), 4u);
    for (int k = 0; k < 3; ++k) {
        const double distance = glm::length(scene.lights[0].position - scene.spheres[k].center);
        EXPECT_NEAR(std::acos(cones[k].cosine), std::asin(0.6 / distance), 1e-3) << k;
    }
    EXPECT_NEAR(std::acos(cones[3].cosine), M_PI / 2, 0.02);
}

}  // namespace
}  // namespace whitted
