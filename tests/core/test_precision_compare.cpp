// Tests for core/precision_compare.*: a scene against itself differs nowhere;
// scenes that differ by construction give the hit, shadow and total internal
// reflection counts that an independent long-double calculation predicts; the
// seed scene in float against double; stopping.
//
// The constructed scenes are rendered in double on both sides and checked to keep
// every pixel centre at least 1e-6 (relative) from a decision boundary, so the
// expected counts hold exactly.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "analysis/precision_compare.h"
#include "image/image_compare.h"
#include "support/core_support.h"

namespace whitted {
namespace {

using LD = long double;
constexpr int kW = 160, kH = 120;

struct V3 {
    LD x, y, z;
    V3 operator+(V3 o) const { return {x + o.x, y + o.y, z + o.z}; }
    V3 operator-(V3 o) const { return {x - o.x, y - o.y, z - o.z}; }
    V3 operator*(LD s) const { return {x * s, y * s, z * s}; }
    LD dot(V3 o) const { return x * o.x + y * o.y + z * o.z; }
    V3 unit() const { return *this * (1 / std::sqrt(dot(*this))); }
};
V3 v3(Vec3 v) {
    return {v.x, v.y, v.z};
}

// The camera ray through the centre of pixel (i, j) for a camera looking down +z
// with up +y (SPEC §1): right is +x.
V3 pixelRay(const Scene& s, int i, int j) {
    const LD t = std::tan(LD(s.camera.vfovDegrees) * 3.14159265358979323846L / 360);
    const LD x = ((i + 0.5L) / kW * 2 - 1) * t * kW / kH, y = (1 - (j + 0.5L) / kH * 2) * t;
    return V3{x, y, 1}.unit();
}

// The distances along unit ray o + t d to a sphere, if the line meets it, and the
// margin of that decision: |r^2 - distance to the line^2| / r^2.
struct LineHit {
    bool meets;
    LD tNear, tFar, margin;
};
LineHit lineSphere(V3 o, V3 d, Vec3 centre, double radius) {
    const V3 f = o - v3(centre);
    const LD b = f.dot(d);
    const V3 closest = f - d * b;
    const LD r2 = LD(radius) * radius, disc = r2 - closest.dot(closest);
    const LD root = disc > 0 ? std::sqrt(disc) : 0;
    return {disc > 0, -b - root, -b + root, std::fabs(disc) / r2};
}

Scene baseScene() {
    Scene s;
    s.camera = Camera{{0, 0, -10}, {0, 0, 0}, {0, 1, 0}, 60};
    s.render.width = kW;
    s.render.height = kH;
    s.render.maxDepth = 0;
    s.render.precision = Precision::Double;
    s.background = {0, 0, 0};
    s.ambient = {0.2, 0.2, 0.2};
    Material wall, ball;
    wall.name = "wall";
    wall.diffuse = {0, 0, 1};
    ball.name = "ball";
    ball.diffuse = {1, 0, 0};
    s.materials = {wall, ball};
    s.spheres = {Sphere{"wall", {0, 0, 20}, 10, "wall"}};
    return s;
}

TEST(CompareScenes, SeedAgainstItself_NoDifferenceInEitherPrecision) {
    for (Precision p : {Precision::Float, Precision::Double}) {
        Scene seed = test::seedScene();
        seed.render.precision = p;
        const PrecisionComparison c = compareScenes(seed, seed, kW, kH);
        SCOPED_TRACE(std::string(precisionName(p)));
        EXPECT_FALSE(c.stopped);
        EXPECT_EQ(c.width, kW);
        EXPECT_EQ(c.height, kH);
        EXPECT_EQ(c.pixels, std::size_t(kW * kH));
        EXPECT_EQ(c.over1, 0u);
        EXPECT_EQ(c.over2, 0u);
        EXPECT_EQ(c.largest, 0.0f);
        EXPECT_EQ(c.hitDiffers, 0u);
        EXPECT_EQ(c.shadowDiffers, 0u);
        EXPECT_EQ(c.tirDiffers, 0u);
        ASSERT_EQ(c.heatMap.width, kW);
        ASSERT_EQ(c.heatMap.height, kH);
        for (float v : c.heatMap.rgb) ASSERT_EQ(v, 0.0f);
    }
}

// A red ball in front of a blue wall, against the wall alone, no lights: the ball's
// pixels, and only they, take another hit and change colour.
TEST(CompareScenes, BallAddedInFront_HitCountIsTheBallsPixels) {
    const Scene a = baseScene();
    Scene b = a;
    b.spheres.push_back(Sphere{"ball", {1, 0.5, 0}, 1.5, "ball"});

    std::size_t expected = 0;
    LD margin = 1;
    for (int j = 0; j < kH; ++j)
        for (int i = 0; i < kW; ++i) {
            const LineHit h = lineSphere(v3(a.camera.position), pixelRay(a, i, j),
                                         b.spheres[1].center, b.spheres[1].radius);
            margin = std::min(margin, h.margin);
            expected += h.meets;
        }
    ASSERT_GT(margin, 1e-6L) << "a pixel centre grazes the ball: the count is not robust";
    ASSERT_GT(expected, 500u);

    const PrecisionComparison c = compareScenes(a, b, kW, kH);
    EXPECT_FALSE(c.stopped);
    EXPECT_EQ(c.hitDiffers, expected);
    EXPECT_EQ(c.shadowDiffers, 0u);
    EXPECT_EQ(c.tirDiffers, 0u);
    // Red on blue or black: every one of those pixels, and no other, differs strongly.
    EXPECT_EQ(c.over1, expected);
    EXPECT_EQ(c.over2, expected);
    EXPECT_GT(c.largest, 100.0f / 255.0f);
}

// A light high above and a small ball out of the camera's view between it and the
// wall: the same hits everywhere, a shadow on the wall.
TEST(CompareScenes, OccluderOutOfView_ShadowCountIsItsShadowOnTheWall) {
    Scene a = baseScene();
    a.lights = {Light{"key", {0, 20, -10}, {1, 1, 1}, 1}};
    Scene b = a;
    b.spheres.push_back(Sphere{"occluder", {0, 16, -6}, 0.5, "ball"});
    const Vec3 light = a.lights[0].position;
    const Sphere& wall = a.spheres[0];
    const Sphere& occluder = b.spheres[1];

    std::size_t expected = 0;
    LD margin = 1;
    for (int j = 0; j < kH; ++j)
        for (int i = 0; i < kW; ++i) {
            const V3 o = v3(a.camera.position), d = pixelRay(a, i, j);
            const LineHit seen = lineSphere(o, d, occluder.center, occluder.radius);
            ASSERT_FALSE(seen.meets && seen.tFar > 0) << "the occluder is in view";
            const LineHit w = lineSphere(o, d, wall.center, wall.radius);
            if (!w.meets) continue;
            const V3 p = o + d * w.tNear, n = (p - v3(wall.center)).unit();
            const V3 toLight = v3(light) - p;
            const LD distance = std::sqrt(toLight.dot(toLight));
            const V3 l = toLight * (1 / distance);
            if (n.dot(l) <= 0) continue;  // not tested: no shadow decision either way
            const LineHit s = lineSphere(p, l, occluder.center, occluder.radius);
            const bool blocked = s.meets && s.tNear > 0 && s.tFar < distance;
            if (s.meets || s.margin < 1e-3L) margin = std::min({margin, s.margin, n.dot(l)});
            expected += blocked;
        }
    ASSERT_GT(margin, 1e-6L) << "a shadow ray grazes the occluder: the count is not robust";
    ASSERT_GT(expected, 300u);

    const PrecisionComparison c = compareScenes(a, b, kW, kH);
    EXPECT_FALSE(c.stopped);
    EXPECT_EQ(c.hitDiffers, 0u);
    EXPECT_EQ(c.shadowDiffers, expected);
    EXPECT_EQ(c.tirDiffers, 0u);
    EXPECT_GE(c.over2, expected * 9 / 10);  // the shadow is dark on a lit wall
    EXPECT_LE(c.over1, expected);
}

// The camera inside a glass ball, off its centre: a ray meets the surface from
// within at sin(i) = |(o - c) x d| / r. With ior 1.5 it is totally reflected above
// sin(i) = 1/1.5; with ior 1.05 only above 1/1.05. The pixels between flip.
TEST(CompareScenes, IorLowered_TirCountIsTheRingBetweenTheCriticalAngles) {
    Scene a = baseScene();
    a.camera = Camera{{1.8, 0, 0}, {1.8, 0, 1}, {0, 1, 0}, 90};
    Material glass;
    glass.name = "glass";
    glass.diffuse = {0, 0, 0};
    glass.transparency = 0.9;
    glass.ior = 1.5;
    a.materials.push_back(glass);
    a.spheres = {Sphere{"glass ball", {0, 0, 0}, 2, "glass"}};
    a.render.maxDepth = 1;
    a.background = {0.5, 0.6, 0.7};
    Scene b = a;
    b.materials[2].ior = 1.05;

    std::size_t expected = 0;
    LD margin = 1;
    const V3 o = v3(a.camera.position);
    for (int j = 0; j < kH; ++j)
        for (int i = 0; i < kW; ++i) {
            const V3 d = pixelRay(a, i, j);
            const LineHit h = lineSphere(o, d, {0, 0, 0}, 2);
            const V3 n = (o + d * h.tFar).unit();  // outward at the exit point
            const LD cosi = d.dot(n), sin2 = 1 - cosi * cosi;
            const bool tirA = sin2 > 1 / (1.5L * 1.5L), tirB = sin2 > 1 / (1.05L * 1.05L);
            margin = std::min(
                {margin, std::fabs(sin2 * 1.5L * 1.5L - 1), std::fabs(sin2 * 1.05L * 1.05L - 1)});
            expected += tirA != tirB;
        }
    ASSERT_GT(margin, 1e-6L) << "a ray meets the surface at a critical angle";
    ASSERT_GT(expected, 300u);

    const PrecisionComparison c = compareScenes(a, b, kW, kH);
    EXPECT_FALSE(c.stopped);
    EXPECT_EQ(c.hitDiffers, 0u);
    EXPECT_EQ(c.shadowDiffers, 0u);
    EXPECT_EQ(c.tirDiffers, expected);
    EXPECT_LT(expected, c.pixels);  // outside the ring both agree
    std::printf("total internal reflection flips in %zu of %zu pixels\n", expected, c.pixels);
}

// The contract's figure for the seed: at most 0.1 % of pixels differ by
// more than 2/255 between float and double.
TEST(ComparePrecisions, SeedScene_FloatAndDoubleAgreeAlmostEverywhere) {
    const Scene seed = test::seedScene();
    const PrecisionComparison c = comparePrecisions(seed, 320, 240);
    EXPECT_FALSE(c.stopped);
    EXPECT_EQ(c.pixels, 320u * 240u);
    EXPECT_LE(c.over2, c.over1);
    EXPECT_LE(double(c.over2) / double(c.pixels), 0.001);
    EXPECT_LE(double(c.hitDiffers + c.shadowDiffers + c.tirDiffers) / double(c.pixels), 0.001);
    // The counts are those of the two renders compared directly.
    Scene f = seed, d = seed;
    f.render.width = d.render.width = 320;
    f.render.height = d.render.height = 240;
    d.render.precision = Precision::Double;
    const Image fi = test::renderImage(f), di = test::renderImage(d);
    EXPECT_EQ(c.over1, compareImages(fi, di, 1.0f / 255.0f).over);
    EXPECT_EQ(c.over2, compareImages(fi, di, 2.0f / 255.0f).over);
    EXPECT_EQ(c.largest, compareImages(fi, di, 0.0f).largest);
    std::printf(
        "seed 320x240: over 1/255 %zu, over 2/255 %zu, largest %.2f/255, hit %zu, "
        "shadow %zu, tir %zu\n",
        c.over1, c.over2, c.largest * 255, c.hitDiffers, c.shadowDiffers, c.tirDiffers);
}

TEST(ComparePrecisions, StopAtOnce_StoppedQuickly) {
    const Scene seed = test::seedScene();
    const auto start = std::chrono::steady_clock::now();
    const PrecisionComparison c = comparePrecisions(seed, 1920, 1440, [] { return true; });
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_TRUE(c.stopped);
    EXPECT_LT(seconds, 0.5);  // a full comparison at this size takes several seconds
}

}  // namespace
}  // namespace whitted
