// Tests for core/tracer.*: reflect/refract, then every term of SPEC §3 against a
// hand-computed pixel, in float and double.
//
// Most scenes here are a 1x1 image from a camera at the origin looking down +z, so
// the only ray is the centre ray, exactly (0,0,1). It hits a unit sphere at (0,0,5)
// at P = (0,0,4) with N = (0,0,-1) and V = (0,0,-1).
//
// Tolerance: pixels are compared to 1e-5 relative (plus 1e-7 absolute for values
// near zero) in both precisions; the image stores float, and a float render loses a
// few ulps (1.2e-7 each) per operation (test::expectColour, tests/support/core_support.h).
#include <cmath>
#include <cstdio>
#include <ostream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "support/core_support.h"
#include "tracer/renderer.h"
#include "tracer/tracer.h"

namespace whitted {

// Readable parameter names in test listings (found by argument-dependent lookup).
inline void PrintTo(Precision p, std::ostream* os) {
    *os << precisionName(p);
}

namespace {

RenderResult renderOneThread(const Scene& s) {
    RenderOptions o;
    o.threads = 1;
    o.progressive = false;
    return render(s, o);
}

Vec3 centrePixel(const Scene& s, RayCounts* rays = nullptr) {
    const RenderResult r = renderOneThread(s);
    EXPECT_TRUE(r.completed);
    if (rays) *rays = r.rays;
    const int x = r.image.width / 2, y = r.image.height / 2;
    const float* p = r.image.pixel(x, y);
    return {p[0], p[1], p[2]};
}

// ---- reflect / refract -------------------------------------------------------

template <typename T>
class ReflectRefractTest : public ::testing::Test {};
using Precisions = ::testing::Types<float, double>;
TYPED_TEST_SUITE(ReflectRefractTest, Precisions);

TYPED_TEST(ReflectRefractTest, Reflect_MirrorsAboutNormal) {
    using T = TypeParam;
    const T s = T(1) / std::sqrt(T(2));
    // (1,-1,0)/sqrt2 off the plane y = 0 goes to (1,1,0)/sqrt2.
    const Vec<T> r = reflect(Vec<T>{s, -s, 0}, Vec<T>{0, 1, 0});
    EXPECT_NEAR(r.x, s, 1e-6);
    EXPECT_NEAR(r.y, s, 1e-6);
    EXPECT_NEAR(r.z, 0, 1e-6);
    // Normal incidence comes straight back.
    const Vec<T> back = reflect(Vec<T>{0, 0, 1}, Vec<T>{0, 0, -1});
    EXPECT_EQ(back, (Vec<T>{0, 0, -1}));
}

TYPED_TEST(ReflectRefractTest, RefractIntoGlass_BendsTowardsNormalBySnell) {
    using T = TypeParam;
    // 30 degrees incidence, eta = 1/1.5: sin t = 0.5/1.5 = 1/3, cos t = sqrt(8/9) = 0.9428090.
    const Vec<T> d{T(0.5), -std::sqrt(T(0.75)), 0};
    auto t = refract(d, Vec<T>{0, 1, 0}, T(1) / T(1.5));
    ASSERT_TRUE(t);
    EXPECT_NEAR(t->x, 1.0 / 3.0, 1e-6);
    EXPECT_NEAR(t->y, -0.9428090415820634, 1e-6);
    EXPECT_NEAR(t->z, 0, 1e-6);
}

TYPED_TEST(ReflectRefractTest, RefractOutOfGlass_BendsAwayFromNormal) {
    using T = TypeParam;
    // 30 degrees from inside, eta = 1.5: sin t = 0.75, cos t = sqrt(1 - 0.5625) = 0.6614378.
    const Vec<T> d{T(0.5), -std::sqrt(T(0.75)), 0};
    auto t = refract(d, Vec<T>{0, 1, 0}, T(1.5));
    ASSERT_TRUE(t);
    EXPECT_NEAR(t->x, 0.75, 1e-6);
    EXPECT_NEAR(t->y, -0.6614378277661477, 1e-6);
}

TYPED_TEST(ReflectRefractTest, RefractBeyondCriticalAngle_ReturnsNothing) {
    using T = TypeParam;
    // Critical angle for 1.5: asin(1/1.5) = 41.8 degrees. At 60: 1.5 sin 60 = 1.30 > 1.
    const Vec<T> d{std::sqrt(T(0.75)), T(-0.5), 0};
    EXPECT_FALSE(refract(d, Vec<T>{0, 1, 0}, T(1.5)));
    // Grazing (89.9 degrees) and exactly tangent.
    const T g = T(89.9 * M_PI / 180);
    EXPECT_FALSE(refract(Vec<T>{std::sin(g), -std::cos(g), 0}, Vec<T>{0, 1, 0}, T(1.5)));
    EXPECT_FALSE(refract(Vec<T>{1, 0, 0}, Vec<T>{0, 1, 0}, T(1.5)));
}

TYPED_TEST(ReflectRefractTest, RefractAtEveryAngle_IsUnitSnellOrNothingNeverNaN) {
    using T = TypeParam;
    for (const double eta : {1 / 1.5, 1.5, 1.0, 2.4, 1 / 2.4}) {
        for (int k = 0; k <= 900; ++k) {
            const double angle = k * 0.1 * M_PI / 180;  // 0 to 90 degrees in 0.1 steps
            const double sinI = std::sin(angle);
            const Vec<T> d{T(sinI), T(-std::cos(angle)), 0};
            auto t = refract(glm::normalize(d), Vec<T>{0, 1, 0}, T(eta));
            const double sinT = eta * sinI;
            if (std::fabs(sinT - 1) < 1e-4) continue;  // at the critical angle either is fine
            ASSERT_EQ(bool(t), sinT < 1) << "eta " << eta << ", angle " << k * 0.1;
            if (!t) continue;
            ASSERT_TRUE(std::isfinite(t->x) && std::isfinite(t->y) && std::isfinite(t->z))
                << "eta " << eta << ", angle " << k * 0.1;
            EXPECT_NEAR(glm::length(*t), 1.0, 1e-5);
            EXPECT_NEAR(t->x, sinT, 1e-5) << "eta " << eta << ", angle " << k * 0.1;
            EXPECT_LE(t->y, T(0));  // through the surface, not back
        }
    }
}

// ---- shading terms, per precision ----------------------------------------------

class ShadingTest : public ::testing::TestWithParam<Precision> {
  protected:
    Scene scene() const { return test::centreRayScene(GetParam()); }
};

std::string precisionLabel(const ::testing::TestParamInfo<Precision>& info) {
    return std::string(precisionName(info.param));
}

TEST_P(ShadingTest, AmbientOnly_IsAmbientTimesDiffuse) {
    Scene s = scene();
    s.ambient = {0.1, 0.2, 0.3};
    s.materials = {test::makeMaterial("m", {0.5, 0.25, 1})};
    s.spheres = {test::makeSphere("ball", {0, 0, 5}, 1, "m")};
    // (0.1*0.5, 0.2*0.25, 0.3*1)
    test::expectColour(centrePixel(s), {0.05, 0.05, 0.3}, "ambient");
}

TEST_P(ShadingTest, NothingHit_IsBackground) {
    Scene s = scene();
    s.background = {0.25, 0.5, 0.125};
    s.ambient = {1, 1, 1};
    s.materials = {test::makeMaterial("m", {1, 1, 1})};
    s.spheres = {test::makeSphere("beside", {3, 0, 5}, 1, "m")};
    test::expectColour(centrePixel(s), {0.25, 0.5, 0.125}, "background");
}

// Light at (0,3,0): L = ((0,3,0) - (0,0,4)) / 5 = (0, 0.6, -0.8), so N.L = 0.8.
// c = (1, 0.5, 0.25) * 2 = (2, 1, 0.5).
Light keyLight() {
    return test::makeLight("key", {0, 3, 0}, {1, 0.5, 0.25}, 2);
}

TEST_P(ShadingTest, Diffuse_IsLightTimesKdTimesNdotL) {
    Scene s = scene();
    s.ambient = {0.1, 0.1, 0.1};
    s.materials = {test::makeMaterial("m", {0.5, 0.5, 0.5})};
    s.lights = {keyLight()};
    s.spheres = {test::makeSphere("ball", {0, 0, 5}, 1, "m")};
    // 0.1*0.5 + (2,1,0.5) * 0.5 * 0.8 = 0.05 + (0.8, 0.4, 0.2)
    test::expectColour(centrePixel(s), {0.85, 0.45, 0.25}, "diffuse");
}

TEST_P(ShadingTest, LightIntensityScalesLinearlyWithoutFalloff) {
    Scene s = scene();
    s.materials = {test::makeMaterial("m", {0.5, 0.5, 0.5})};
    // Same direction as keyLight but 10x further: (0,30,-36); no fall-off with distance.
    s.lights = {test::makeLight("far", {0, 30, 4 - 40}, {1, 1, 1}, 0.5)};
    s.spheres = {test::makeSphere("ball", {0, 0, 5}, 1, "m")};
    // 0.5 * 0.5 * 0.8 = 0.2
    test::expectColour(centrePixel(s), {0.2, 0.2, 0.2}, "far light");
}

TEST_P(ShadingTest, Specular_IsKsTimesNdotHToTheShininess) {
    Scene s = scene();
    Material m = test::makeMaterial("m", {0, 0, 0});
    m.specular = 0.5;
    m.shininess = 10;
    s.materials = {m};
    s.lights = {keyLight()};
    s.spheres = {test::makeSphere("ball", {0, 0, 5}, 1, "m")};
    // H = normalize(L + V) = normalize(0, 0.6, -1.8); N.H = 1.8 / sqrt(3.6), (N.H)^2 = 0.9,
    // so (N.H)^10 = 0.9^5 = 0.59049. colour = (2,1,0.5) * 0.5 * 0.59049.
    test::expectColour(centrePixel(s), {0.59049, 0.295245, 0.1476225}, "specular, n = 10");

    s.materials[0].shininess = 10.5;  // not a whole number: (N.H)^10.5 = 0.9^5.25 = 0.5751395
    test::expectColour(
        centrePixel(s),
        {2 * 0.5 * 0.5751394722266736, 0.5 * 0.5751394722266736, 0.25 * 0.5751394722266736},
        "specular, n = 10.5");

    s.materials[0].diffuse = {0.5, 0.5, 0.5};  // diffuse and specular add up
    s.materials[0].shininess = 10;
    test::expectColour(centrePixel(s), {0.8 + 0.59049, 0.4 + 0.295245, 0.2 + 0.1476225},
                       "diffuse + specular");
}

TEST_P(ShadingTest, LightBehindSurface_GivesNoDiffuseAndNoSpecular) {
    Scene s = scene();
    s.ambient = {0.1, 0.1, 0.1};
    Material m = test::makeMaterial("m", {0.5, 0.5, 0.5});
    m.specular = 1;
    m.shininess = 1;
    s.materials = {m};
    // Light at (0,10,5): L = (0,10,1)/sqrt(101), N.L = -0.0995 < 0, but
    // N.H = 0.67 > 0: the specular term must still be skipped (only where N.L > 0).
    s.lights = {test::makeLight("above", {0, 10, 5}, {1, 1, 1}, 1)};
    s.spheres = {test::makeSphere("ball", {0, 0, 5}, 1, "m")};
    test::expectColour(centrePixel(s), {0.05, 0.05, 0.05}, "ambient only");
}

// Blockers on the segment from P = (0,0,4) to the light (0,3,0): P + s (0,3,-4) at
// s = 0.25 -> (0,0.75,3) and s = 0.5 -> (0,1.5,2). Both are off the camera ray.
TEST_P(ShadingTest, ShadowThroughTransparentSpheres_IsProductOfTransparencies) {
    Scene s = scene();
    s.ambient = {0.1, 0.1, 0.1};
    Material glassA = test::makeMaterial("glassA", {0, 0, 0});
    glassA.transparency = 0.5;
    Material glassB = test::makeMaterial("glassB", {0, 0, 0});
    glassB.transparency = 0.4;
    s.materials = {test::makeMaterial("m", {0.5, 0.5, 0.5}), glassA, glassB};
    s.lights = {keyLight()};
    s.spheres = {test::makeSphere("ball", {0, 0, 5}, 1, "m"),
                 test::makeSphere("a", {0, 1.5, 2}, 0.5, "glassA")};
    // S = 0.5: 0.05 + 0.5 * (0.8, 0.4, 0.2)
    test::expectColour(centrePixel(s), {0.45, 0.25, 0.15}, "one blocker, S = 0.5");
    s.spheres.push_back(test::makeSphere("b", {0, 0.75, 3}, 0.3, "glassB"));
    // S = 0.5 * 0.4 = 0.2: 0.05 + 0.2 * (0.8, 0.4, 0.2)
    test::expectColour(centrePixel(s), {0.21, 0.13, 0.09}, "two blockers, S = 0.2");
}

TEST_P(ShadingTest, ShadowByOpaqueSphere_LeavesAmbientOnly) {
    Scene s = scene();
    s.ambient = {0.1, 0.1, 0.1};
    Material m = test::makeMaterial("m", {0.5, 0.5, 0.5});
    m.specular = 1;
    s.materials = {m, test::makeMaterial("opaque", {1, 1, 1})};
    s.lights = {keyLight()};
    s.spheres = {test::makeSphere("ball", {0, 0, 5}, 1, "m"),
                 test::makeSphere("blocker", {0, 1.5, 2}, 0.5, "opaque")};
    test::expectColour(centrePixel(s), {0.05, 0.05, 0.05}, "full shadow");
}

TEST_P(ShadingTest, SphereBeyondLightOrBesideShadowRay_CastsNoShadow) {
    Scene s = scene();
    s.ambient = {0.1, 0.1, 0.1};
    s.materials = {test::makeMaterial("m", {0.5, 0.5, 0.5}),
                   test::makeMaterial("opaque", {1, 1, 1})};
    s.lights = {keyLight()};
    // Beyond the light on the same line (s = 1.5 -> (0,4.5,-2)), and beside the segment.
    s.spheres = {test::makeSphere("ball", {0, 0, 5}, 1, "m"),
                 test::makeSphere("beyond", {0, 4.5, -2}, 0.5, "opaque"),
                 test::makeSphere("beside", {2, 1.5, 2}, 0.5, "opaque")};
    test::expectColour(centrePixel(s), {0.85, 0.45, 0.25}, "unshadowed");
}

TEST_P(ShadingTest, Mirror_AddsReflectivityTimesBackground) {
    Scene s = scene();
    s.ambient = {0.1, 0.1, 0.1};
    s.background = {0.4, 0.6, 0.8};
    Material m = test::makeMaterial("mirror", {0.2, 0.2, 0.2});
    m.reflectivity = 0.5;
    s.materials = {m};
    s.spheres = {test::makeSphere("ball", {0, 0, 5}, 1, "mirror")};
    // The reflected ray goes back along -z and hits nothing: 0.02 + 0.5 * background.
    test::expectColour(centrePixel(s), {0.22, 0.32, 0.42}, "mirror, max_depth 5");
    s.render.maxDepth = 0;  // no secondary rays at all
    test::expectColour(centrePixel(s), {0.02, 0.02, 0.02}, "mirror, max_depth 0");
    // A single bounce exists: depth 1 and 2 give the same picture.
    s.render.maxDepth = 1;
    const Vec3 one = centrePixel(s);
    s.render.maxDepth = 2;
    EXPECT_EQ(one, centrePixel(s));
}

// Two mirrors of reflectivity 0.5 facing each other through the camera: A
// at z = 5 in front, B at z = -5 behind, so the centre's ray bounces between them.
Scene facingMirrors(Scene s) {
    s.ambient = {0.1, 0.1, 0.1};
    Material m = test::makeMaterial("mirror", {0.2, 0.2, 0.2});
    m.reflectivity = 0.5;
    s.materials = {m};
    s.spheres = {test::makeSphere("A", {0, 0, 5}, 1, "mirror"),
                 test::makeSphere("B", {0, 0, -5}, 1, "mirror")};
    return s;
}

TEST_P(ShadingTest, FacingMirrors_EachDepthAddsOneBounce) {
    Scene s = facingMirrors(scene());
    // Each hit adds e = 0.1 * 0.2 = 0.02 weighted by 0.5^bounce:
    // depth 0: 0.02, 1: 0.03, 2: 0.035, 3: 0.0375.
    const double expected[] = {0.02, 0.03, 0.035, 0.0375};
    for (int depth = 0; depth <= 3; ++depth) {
        s.render.maxDepth = depth;
        RayCounts rays;
        const Vec3 c = centrePixel(s, &rays);
        test::expectColour(c, Vec3(expected[depth]),
                           ("max_depth " + std::to_string(depth)).c_str());
        EXPECT_EQ(rays.camera, 1u);
        EXPECT_EQ(rays.reflection, std::uint64_t(depth)) << "max_depth " << depth;
        EXPECT_EQ(rays.refraction, 0u);
        EXPECT_EQ(rays.shadow, 0u);
    }
}

TEST_P(ShadingTest, FacingMirrors_PruningWeightEndsAPathLighterThanIt) {
    Scene s = facingMirrors(scene());
    s.render.maxDepth = 10;
    // The bounces pass on 0.5, 0.25, 0.125, ...: a ray of weight 0.25 is still
    // traced at 0.25 (at or above), not at 0.26; at 0.2 the third is not.
    const struct {
        double prune;
        int reflections;
        double colour;
    } cases[] = {{0.25, 2, 0.035}, {0.26, 1, 0.03}, {0.2, 2, 0.035}, {0.1, 3, 0.0375}};
    for (const auto& c : cases) {
        RenderOptions o = oneShotOptions();
        o.threads = 1;
        o.pruneBelowWeight = c.prune;
        const RenderResult r = render(s, o);
        const float* p = r.image.pixel(r.image.width / 2, r.image.height / 2);
        const std::string label = "prune below " + std::to_string(c.prune);
        test::expectColour({p[0], p[1], p[2]}, Vec3(c.colour), label.c_str());
        EXPECT_EQ(r.rays.reflection, std::uint64_t(c.reflections)) << label;
    }
}

TEST_P(ShadingTest, Glass_AddsTransparencyTimesWhatIsBehind) {
    Scene s = scene();
    s.ambient = {0.5, 0.5, 0.5};
    Material glass = test::makeMaterial("glass", {0, 0, 0});
    glass.transparency = 0.8;
    glass.ior = 1.5;
    s.materials = {glass, test::makeMaterial("red", {1, 0, 0})};
    // Normal incidence: the ray goes straight through the glass (z 4 to 6) and hits
    // the red ball at z = 9, whose colour is ambient * kd = (0.5, 0, 0). Entering and
    // leaving the glass each weigh 0.8: 0.64 * (0.5, 0, 0).
    s.spheres = {test::makeSphere("glass", {0, 0, 5}, 1, "glass"),
                 test::makeSphere("red", {0, 0, 10}, 1, "red")};
    s.render.maxDepth = 2;
    RayCounts rays;
    test::expectColour(centrePixel(s, &rays), {0.32, 0, 0}, "glass, max_depth 2");
    EXPECT_EQ(rays.refraction, 2u);
    EXPECT_EQ(rays.reflection, 0u);
    s.render.maxDepth = 1;  // the ray inside the glass may not leave it
    test::expectColour(centrePixel(s), {0, 0, 0}, "glass, max_depth 1");
    s.render.maxDepth = 0;
    test::expectColour(centrePixel(s), {0, 0, 0}, "glass, max_depth 0");

    s.spheres.pop_back();  // now the background is behind
    s.background = {0.5, 0.25, 1};
    s.render.maxDepth = 5;
    test::expectColour(centrePixel(s), {0.32, 0.16, 0.64}, "glass over background");
}

TEST_P(ShadingTest, TotalInternalReflection_SendsTransparencyShareAlongReflection) {
    Scene s = scene();
    // Camera inside a unit glass sphere at the origin, 0.9 off centre, looking down +z:
    // the ray meets the surface at 64 degrees incidence (sin = 0.9); 1.5 * 0.9 > 1, so
    // every hit is a total internal reflection and the ray stays trapped.
    s.camera.position = {0, 0.9, 0};
    s.camera.lookAt = {0, 0.9, 1};
    s.ambient = {1, 1, 1};
    s.background = {1, 1, 1};
    Material glass = test::makeMaterial("glass", {0.1, 0.1, 0.1});
    glass.transparency = 1;
    glass.ior = 1.5;
    s.materials = {glass};
    s.spheres = {test::makeSphere("glass", {0, 0, 0}, 1, "glass")};
    // Each hit adds ambient * kd = 0.1, carried on with weight kt = 1: 0.1 * (max_depth + 1).
    // Dropping the kt share would give 0.1; refracting out would show the background.
    for (int depth : {0, 1, 3}) {
        s.render.maxDepth = depth;
        RayCounts rays;
        test::expectColour(centrePixel(s, &rays), Vec3(0.1 * (depth + 1)),
                           ("TIR, max_depth " + std::to_string(depth)).c_str());
        EXPECT_EQ(rays.reflection, std::uint64_t(depth));
        EXPECT_EQ(rays.refraction, 0u);
    }
    // With ior 1 nothing bends and there is no TIR: 0.1 + 1 * background.
    s.materials[0].ior = 1;
    s.render.maxDepth = 3;
    test::expectColour(centrePixel(s), Vec3(1.1), "ior 1");
}

struct CheckerCase {
    Vec3 hitPoint;  // the centre ray's hit point
    double size;
    bool odd;  // floor(x/s) + floor(y/s) + floor(z/s) is odd
};

TEST_P(ShadingTest, Checker_OddCellsUseCheckerColour) {
    // floor sums: (0.3,0.1,4.6)/1 -> 0+0+4 even; /1.5 -> 0+0+3 odd;
    // (-0.3,0.1,4.6)/1 -> -1+0+4 odd; (-0.3,-0.1,4.6)/1 -> -1-1+4 even;
    // (1.3,0.1,4.6)/1 -> 1+0+4 odd; (0.3,0.1,4.6)/0.35 -> 0+0+13 odd; /0.7 -> 0+0+6 even.
    const CheckerCase cases[] = {
        {{0.3, 0.1, 4.6}, 1, false},   {{0.3, 0.1, 4.6}, 1.5, true}, {{-0.3, 0.1, 4.6}, 1, true},
        {{-0.3, -0.1, 4.6}, 1, false}, {{1.3, 0.1, 4.6}, 1, true},   {{0.3, 0.1, 4.6}, 0.35, true},
        {{0.3, 0.1, 4.6}, 0.7, false},
    };
    const Vec3 diffuse{0.25, 0.5, 0.75}, checkerColour{0.9, 0.1, 0.2};
    for (const CheckerCase& c : cases) {
        Scene s = scene();
        s.ambient = {1, 1, 1};  // the pixel is kd(P) itself
        const Vec3 cam{c.hitPoint.x, c.hitPoint.y, 0};
        s.camera.position = cam;
        s.camera.lookAt = cam + Vec3{0, 0, 1};
        Material m = test::makeMaterial("checker", diffuse);
        m.checker = Checker{checkerColour, c.size};
        s.materials = {m};
        s.spheres = {test::makeSphere("ball", c.hitPoint + Vec3{0, 0, 1}, 1, "checker")};
        const std::string what = "P = (" + std::to_string(c.hitPoint.x) + ", " +
                                 std::to_string(c.hitPoint.y) + ", " +
                                 std::to_string(c.hitPoint.z) + "), size " + std::to_string(c.size);
        test::expectColour(centrePixel(s), c.odd ? checkerColour : diffuse, what.c_str());
    }
}

TEST_P(ShadingTest, CameraLookingDownPlusZ_SeesPlusXOnTheRightAndPlusYAtTheTop) {
    Scene s = scene();
    s.render.width = 64;
    s.render.height = 48;
    s.ambient = {1, 1, 1};
    s.materials = {test::makeMaterial("white", {1, 1, 1})};
    // vfov 60: at z = 5 the view spans x in +-5 tan30 * 4/3 = +-3.85 and y in +-2.89.
    s.spheres = {test::makeSphere("right", {2, 0, 5}, 1, "white")};
    const Image right = renderOneThread(s).image;
    s.spheres = {test::makeSphere("up", {0, 1.5, 5}, 1, "white")};
    const Image up = renderOneThread(s).image;
    double left = 0, rightHalf = 0, top = 0, bottom = 0;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x) {
            (x < 32 ? left : rightHalf) += right.pixel(x, y)[0];
            (y < 24 ? top : bottom) += up.pixel(x, y)[0];
        }
    EXPECT_EQ(left, 0) << "sphere at +x shows in the left half";
    EXPECT_GT(rightHalf, 50);
    EXPECT_EQ(bottom, 0) << "sphere at +y shows in the bottom half";
    EXPECT_GT(top, 50);
    // The centre of the +x sphere: x = 0.4 / (tan30 * 4/3) = 0.52 -> column (0.52+1)/2*64 = 48.6.
    EXPECT_EQ(right.pixel(48, 24)[0], 1.0f);
    EXPECT_EQ(right.pixel(64 - 49, 24)[0], 0.0f);
}

TEST_P(ShadingTest, GlassHeavyScene_HasNoNaNOrInfinitePixels) {
    Scene s = scene();
    s.render.width = 48;
    s.render.height = 32;
    s.render.maxDepth = 8;
    s.camera.position = {0, 0.35, -1};
    s.camera.lookAt = {0, 0.25, 0};
    s.ambient = {0.05, 0.05, 0.05};
    s.background = {0.2, 0.3, 0.4};
    Material glass = test::makeMaterial("glass", {0, 0, 0});
    glass.specular = 1;
    glass.shininess = 200;
    glass.reflectivity = 0.1;
    glass.transparency = 0.9;
    glass.ior = 1.5;
    Material dense = glass;
    dense.name = "dense";
    dense.ior = 2.4;
    Material floor = test::makeMaterial("floor", {0.75, 0.75, 0.75});
    floor.checker = Checker{{0, 0, 0}, 0.5};
    floor.reflectivity = 0.25;
    s.materials = {glass, dense, floor};
    s.lights = {test::makeLight("key", {5, 5, -10}, {1, 1, 1}, 1)};
    s.spheres = {test::makeSphere("a", {0.5, 0.2, 1.5}, 0.6, "glass"),
                 test::makeSphere("b", {-0.5, 0.3, 1.2}, 0.5, "dense"),
                 test::makeSphere("inner", {0.5, 0.2, 1.5}, 0.3, "dense"),  // nested in a
                 test::makeSphere("floor", {0, -99999.5, 0}, 99999, "floor")};
    const Image img = renderOneThread(s).image;
    for (size_t k = 0; k < img.rgb.size(); ++k)
        ASSERT_TRUE(std::isfinite(img.rgb[k])) << "component " << k << " is " << img.rgb[k];
}

// ---- secondary rays only where the scene can use them (SPEC §3, last point) ----

Scene rayCountScene(Precision p) {
    Scene s = test::centreRayScene(p);
    s.render.width = 16;
    s.render.height = 12;
    s.camera.position = {0, 0.35, -1};
    s.camera.lookAt = {0, 0.25, 0};
    s.ambient = {0.05, 0.05, 0.05};
    Material m = test::makeMaterial("m", {0.5, 0.2, 0.1});
    m.specular = 1;
    s.materials = {m};
    s.spheres = {test::makeSphere("ball", {0, 0.2, 2}, 0.6, "m"),
                 test::makeSphere("floor", {0, -99999.5, 0}, 99999, "m")};
    return s;
}

TEST_P(ShadingTest, NoLightsNoMirrorsNoGlass_TracesCameraRaysOnly) {
    Scene s = rayCountScene(GetParam());
    const RayCounts rays = renderOneThread(s).rays;
    EXPECT_EQ(rays.camera, 16u * 12u);
    EXPECT_EQ(rays.shadow, 0u);
    EXPECT_EQ(rays.reflection, 0u);
    EXPECT_EQ(rays.refraction, 0u);
    EXPECT_EQ(rays.total(), 16u * 12u);
}

TEST_P(ShadingTest, LightButNoMirrorsNoGlass_TracesNoReflectionOrRefractionRays) {
    Scene s = rayCountScene(GetParam());
    s.lights = {test::makeLight("key", {5, 5, -10}, {1, 1, 1}, 1)};
    const RayCounts rays = renderOneThread(s).rays;
    EXPECT_EQ(rays.camera, 16u * 12u);
    EXPECT_GT(rays.shadow, 0u);  // every pixel sees the floor or the ball, lit from the front
    EXPECT_LE(rays.shadow, rays.camera);
    EXPECT_EQ(rays.reflection, 0u);
    EXPECT_EQ(rays.refraction, 0u);
}

TEST_P(ShadingTest, DarkLightOrUnlitMaterials_TraceNoShadowRays) {
    Scene s = rayCountScene(GetParam());
    s.lights = {test::makeLight("off", {5, 5, -10}, {1, 1, 1}, 0)};  // c_j = 0
    EXPECT_EQ(renderOneThread(s).rays.shadow, 0u) << "light of intensity 0";
    s.lights = {test::makeLight("black", {5, 5, -10}, {0, 0, 0}, 1)};
    EXPECT_EQ(renderOneThread(s).rays.shadow, 0u) << "light of colour 0";
    s.lights = {test::makeLight("key", {5, 5, -10}, {1, 1, 1}, 1)};
    s.materials[0].diffuse = {0, 0, 0};
    s.materials[0].specular = 0;  // kd = ks = 0: the light term is zero everywhere
    EXPECT_EQ(renderOneThread(s).rays.shadow, 0u) << "black, non-specular material";
}

// prepareScene() fills the spheres on all cores; a sphere naming a missing
// material (a scene not validated first) is refused on the caller's thread,
// in validateScene()'s words, not left to crash a worker.
TEST(PrepareScene, SphereWithMissingMaterial_IsRefusedWithItsPath) {
    Scene s = test::centreRayScene(Precision::Float);
    s.materials = {test::makeMaterial("red", {1, 0, 0})};
    s.spheres = {test::makeSphere("a", {0, 0, 5}, 1, "red"),
                 test::makeSphere("b", {0, 3, 5}, 1, "blue")};
    try {
        prepareScene<float>(s);
        FAIL() << "prepared a scene whose sphere names a missing material";
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()), "spheres[1].material: no material named \"blue\"");
    }
}

INSTANTIATE_TEST_SUITE_P(Precisions, ShadingTest,
                         ::testing::Values(Precision::Float, Precision::Double), precisionLabel);

}  // namespace
}  // namespace whitted
