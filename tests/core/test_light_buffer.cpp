// A light's buffer (light_buffer.h) spares shadow rays the tree's walk, and
// must change no pixel: rows traced with every light's buffer equal rows
// traced through the tree, bit for bit, among random balls of opaque, glass
// and half-clear materials, with lights above the balls, among them, inside
// one and looking along a cube's edges, in both precisions and under every
// kernel. A buffer lists, in the cell a ray's direction picks, every sphere
// the ray crosses on its way to the light; a render thread makes it only when
// its shadow rays are scattered. Seeds printed on failure.
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/core_support.h"
#include "tracer/bvh_traverse.h"
#include "tracer/light_buffer.h"
#include "tracer/tracer.h"

namespace whitted {
namespace {

constexpr int kBalls = 300;

// Balls in a box 8 wide around the origin, a floor, and three lights: one
// high above, one among the balls, and one that sits inside a ball (no buffer
// then) or sees balls straight along its cube's edges and corners.
Scene cloudScene(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> pos(-4.0, 4.0), logR(-1.7, -0.4), unit(0.0, 1.0);
    Scene scene;
    scene.render.width = 40;
    scene.render.height = 24;
    scene.render.maxDepth = 3;
    scene.render.samplesPerPixel = 2;
    scene.materials = {Material{"m", {0.5, 0.2, 0.1}, 1, 50, 0.5, 0, 1.5, Checker{{0, 0, 0}, 0.5}},
                       Material{"glass", {0, 0, 0}, 1, 200, 0.1, 0.9, 1.5, std::nullopt},
                       Material{"haze", {0.2, 0.2, 0.6}, 1, 20, 0.0, 0.5, 1.0, std::nullopt}};
    const char* const kinds[] = {"m", "m", "glass", "haze"};
    scene.spheres = {Sphere{"floor", {0, -99999.5 - 4, 0}, 99999, "m"}};
    for (int k = 0; k < kBalls; ++k)
        scene.spheres.push_back(Sphere{"b" + std::to_string(k),
                                       {pos(rng), pos(rng), pos(rng)},
                                       std::pow(10.0, logR(rng)),
                                       kinds[k % 4]});
    const Vec3 among{pos(rng) * 0.5, pos(rng) * 0.5, pos(rng) * 0.5};
    Vec3 third{pos(rng), pos(rng), pos(rng)};
    if (unit(rng) < 0.3) {
        third = scene.spheres[1].center;
    } else {
        // Balls whose centres lie on the diagonals from the light: their cones
        // straddle two or three faces.
        const Vec3 along[] = {{1, 1, 0}, {1, -1, 1}, {-1, 1, 1}, {0, -1, -1}, {1, 1, 1}};
        for (const Vec3& d : along)
            scene.spheres.push_back(Sphere{"edge", third + (1.5 + 2 * unit(rng)) * d, 0.2, "m"});
    }
    scene.lights = {Light{"above", {0, 40, 0}, {1, 1, 1}, 1},
                    Light{"among", among, {0.5, 0.5, 0.5}, 1},
                    Light{"third", third, {0.3, 0.3, 0.3}, 1}};
    const Vec3 eye{pos(rng) * 0.8, pos(rng) * 0.8, pos(rng) * 0.8};
    const Vec3 ahead = eye + Vec3{pos(rng), pos(rng) * 0.5, pos(rng)} + Vec3(0.01);
    scene.camera = Camera{eye, ahead, {0, 1, 0}, 40.0 + 80.0 * unit(rng)};
    return scene;
}

// Rows of every sample with each light's buffer and through the tree alone:
// equal bit for bit. Returns how many of the lights had a buffer.
template <typename T>
int checkBuffersChangeNoPixel(const Scene& scene, unsigned seed) {
    useAcceleration(Acceleration::bvh);
    const PreparedScene<T> walked = prepareScene<T>(scene);
    PreparedScene<T> buffered = prepareScene<T>(scene);
    useAcceleration(Acceleration::automatic);
    addLightBuffers(buffered, 1);
    int made = 0;
    for (const PreparedLight<T>& light : buffered.lights) made += light.buffer->ready() != nullptr;
    test::expectSameRows(buffered, walked, scene, "seed " + std::to_string(seed));
    return made;
}

TEST(LightBuffer, ChangesNoPixel) {
    test::forEveryKernel([](const std::string&) {
        int made = 0, lights = 0;
        for (unsigned seed = 1; seed <= 8; ++seed) {
            const Scene scene = cloudScene(seed);
            made += checkBuffersChangeNoPixel<float>(scene, seed);
            made += checkBuffersChangeNoPixel<double>(scene, seed);
            lights += 2 * int(scene.lights.size());
        }
        // Most lights get a buffer, or this test would test little; not the
        // ones inside a ball.
        EXPECT_GT(made, lights / 2);
        EXPECT_LT(made, lights);
    });
}

// The segment from p to the light passes through the sphere by more than
// rounding can undo: the shadow ray certainly crosses it.
bool segmentCrosses(const glm::dvec3& p, const glm::dvec3& light, const glm::dvec3& centre,
                    double radius) {
    const glm::dvec3 d = light - p;
    const double t = std::clamp(glm::dot(centre - p, d) / glm::dot(d, d), 0.0, 1.0);
    return glm::length(p + t * d - centre) < radius * (1 - 1e-6);
}

TEST(LightBuffer, ListsEverySphereARayCrossesInItsCell) {
    int crossings = 0, throughTree = 0;
    for (unsigned seed = 1; seed <= 6; ++seed) {
        const Scene scene = cloudScene(seed);
        useAcceleration(Acceleration::bvh);
        const PreparedScene<float> s = prepareScene<float>(scene);
        useAcceleration(Acceleration::automatic);
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> pos(-4.5, 4.5);
        for (const PreparedLight<float>& light : s.lights) {
            const std::shared_ptr<const LightBuffer> buffer =
                lightBuffer(light.position, s.spheres, s.bvh->direct, 1);
            if (!buffer) continue;
            const glm::dvec3 l(light.position);
            for (int ray = 0; ray < 4000; ++ray) {
                const glm::dvec3 p{pos(rng), pos(rng), pos(rng)};
                const Vec<float> d = glm::normalize(Vec<float>(l - p));
                const int c = lightBufferCell(*buffer, d.x, d.y, d.z);
                const LightBufferCell cell = c < 0 ? LightBufferCell{} : buffer->cells[c];
                if (cell.count == LightBufferCell::kThroughTree) {
                    ++throughTree;
                    continue;
                }
                const auto first = buffer->spheres.begin() + cell.first;
                for (int k = 1; k < s.spheres.count(); ++k) {
                    if (!segmentCrosses(p, l, s.spheres.centreOf(k), s.spheres.radiusOf(k)))
                        continue;
                    ++crossings;
                    EXPECT_NE(std::find(first, first + cell.count, k), first + cell.count)
                        << "seed " << seed << " sphere " << k << " not in cell " << c;
                }
            }
        }
    }
    EXPECT_GT(crossings, 3000);
    EXPECT_LT(throughTree, crossings / 10);
}

TEST(LightBuffer, NoneForALightInsideASphere) {
    Scene scene = cloudScene(1);
    scene.lights = {Light{"inside", scene.spheres[5].center, {1, 1, 1}, 1}};
    useAcceleration(Acceleration::bvh);
    const PreparedScene<float> s = prepareScene<float>(scene);
    useAcceleration(Acceleration::automatic);
    EXPECT_EQ(lightBuffer(s.lights[0].position, s.spheres, s.bvh->direct, 1), nullptr);
    scene.lights[0].position.y += 20;
    useAcceleration(Acceleration::bvh);
    const PreparedScene<float> above = prepareScene<float>(scene);
    useAcceleration(Acceleration::automatic);
    EXPECT_NE(lightBuffer(above.lights[0].position, above.spheres, above.bvh->direct, 1), nullptr);
}

// A render thread decides once, after kLightBufferProbe shadow rays of its own:
// a buffer where at least kLoneLeavesPerShadowRay leaf visits a ray were a lane's
// alone, none where the packets kept together.
TEST(LightBuffer, MadeOnlyWhenTheShadowRaysAreScattered) {
    useAcceleration(Acceleration::bvh);
    PreparedScene<float> s = prepareScene<float>(cloudScene(2));
    useAcceleration(Acceleration::automatic);
    s.lights.resize(1);
    const auto decide = [&](std::uint64_t shadow, double lonePerRay) {
        addLightBufferSlots(s);
        RayCounts counts;
        counts.shadow = shadow;
        counts.shadowLoneLeaves = std::uint64_t(lonePerRay * double(shadow));
        considerLightBuffer(s, s.lights[0], counts);
        const bool claimed = s.lights[0].buffer->claimed();
        const bool made = s.lights[0].buffer->ready() != nullptr;
        s.lights[0].buffer = nullptr;
        return std::pair{claimed, made};
    };
    EXPECT_EQ(decide(kLightBufferProbe - 1, 1.0), std::pair(false, false));
    EXPECT_EQ(decide(kLightBufferProbe, kLoneLeavesPerShadowRay / 2), std::pair(true, false));
    EXPECT_EQ(decide(kLightBufferProbe, kLoneLeavesPerShadowRay * 2), std::pair(true, true));
}

}  // namespace
}  // namespace whitted
