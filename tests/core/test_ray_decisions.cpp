// Tests for core/ray_decisions.*: the decision list of hand-built ray trees, the
// decisions against the tracer's own image (a pixel is ambient-only exactly where
// the list says it is shadowed, background exactly where it says miss), and the
// signature and first-difference helpers.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "analysis/ray_decisions.h"
#include "support/core_support.h"
#include "tracer/renderer.h"

namespace whitted {
namespace {

using D = Decision;
constexpr auto kHit = DecisionKind::Hit;
constexpr auto kShadow = DecisionKind::Shadow;
constexpr auto kTir = DecisionKind::Tir;

// A 1x1 image looking down +z from `eye`: the only ray is the centre ray, exactly (0,0,1).
Scene centreRay(Vec3 eye, Precision precision) {
    Scene s;
    s.camera.position = eye;
    s.camera.lookAt = eye + Vec3(0, 0, 1);
    s.render.width = s.render.height = 1;
    s.render.maxDepth = 1;
    s.render.precision = precision;
    return s;
}

template <typename T>
std::vector<Decision> decisionsOf(const Scene& scene, int i = 0, int j = 0) {
    std::vector<Decision> out;
    pixelDecisions(prepareScene<T>(scene), i, j, out);
    return out;
}

template <typename T>
class RayDecisionsTest : public ::testing::Test {};
using Precisions = ::testing::Types<float, double>;
TYPED_TEST_SUITE(RayDecisionsTest, Precisions);

TYPED_TEST(RayDecisionsTest, EmptyScene_OneMiss) {
    const Scene s = centreRay({0, 0, 0}, Precision::Double);
    EXPECT_EQ(decisionsOf<TypeParam>(s), (std::vector<D>{{kHit, -1}}));
}

TYPED_TEST(RayDecisionsTest, Mirror_HitThenReflectedMiss_OneShadowPerLight) {
    Scene s = centreRay({0, 0, 0}, Precision::Double);
    Material mirror = test::makeMaterial("mirror", {0.5, 0.5, 0.5});
    mirror.reflectivity = 1;
    s.materials = {mirror};
    s.spheres = {Sphere{"ball", {0, 0, 5}, 1, "mirror"}};
    // In front of the ball (lit, nothing between), behind it (N.L < 0: not tested).
    s.lights = {Light{"front", {0, 3, -3}, {1, 1, 1}, 1}, Light{"back", {0, 0, 10}, {1, 1, 1}, 1}};
    EXPECT_EQ(decisionsOf<TypeParam>(s),
              (std::vector<D>{{kHit, 0}, {kShadow, 0}, {kShadow, 0}, {kHit, -1}}));
    // A dark light is no light at all: no decision for it.
    s.lights[1].intensity = 0;
    EXPECT_EQ(decisionsOf<TypeParam>(s), (std::vector<D>{{kHit, 0}, {kShadow, 0}, {kHit, -1}}));
    // At depth 0 nothing is spawned.
    s.render.maxDepth = 0;
    EXPECT_EQ(decisionsOf<TypeParam>(s), (std::vector<D>{{kHit, 0}, {kShadow, 0}}));
}

TYPED_TEST(RayDecisionsTest, Occluder_ShadowBitSet) {
    Scene s = centreRay({0, 0, 0}, Precision::Double);
    s.materials = {test::makeMaterial("grey", {0.5, 0.5, 0.5})};
    // The hit point is (0,0,4); the way to the light passes (0,2,2.4) at 0.4 of its length.
    s.spheres = {Sphere{"ball", {0, 0, 5}, 1, "grey"}, Sphere{"blocker", {0, 2, 2.4}, 0.5, "grey"}};
    s.lights = {Light{"key", {0, 5, 0}, {1, 1, 1}, 1}};
    EXPECT_EQ(decisionsOf<TypeParam>(s), (std::vector<D>{{kHit, 0}, {kShadow, 1}}));
    s.spheres[1].center = {3, 2, 2.4};  // beside the shadow ray
    EXPECT_EQ(decisionsOf<TypeParam>(s), (std::vector<D>{{kHit, 0}, {kShadow, 0}}));
}

// Camera inside a glass ball of radius 1 at (0.9, 0, 0) from its centre: the centre
// ray meets the surface at sin(i) = 0.9. Beyond the critical angle (ior 1.5:
// sin = 1/1.5) the whole share is reflected and hits the ball again; below it
// (ior 1.05: sin = 0.952) the ray leaves.
TYPED_TEST(RayDecisionsTest, CameraInGlass_TirDecidedBySnell) {
    Scene s = centreRay({0.9, 0, 0}, Precision::Double);
    Material glass = test::makeMaterial("glass", {0, 0, 0});
    glass.transparency = 0.9;
    glass.ior = 1.5;
    s.materials = {glass};
    s.spheres = {Sphere{"glass ball", {0, 0, 0}, 1, "glass"}};
    s.render.maxDepth = 2;
    EXPECT_EQ(decisionsOf<TypeParam>(s),
              (std::vector<D>{{kHit, 0}, {kTir, 1}, {kHit, 0}, {kTir, 1}, {kHit, 0}}));
    s.materials[0].ior = 1.05;
    EXPECT_EQ(decisionsOf<TypeParam>(s), (std::vector<D>{{kHit, 0}, {kTir, 0}, {kHit, -1}}));
    // With a mirror share the reflected tree follows the refracted one.
    s.materials[0].reflectivity = 0.1;
    EXPECT_EQ(decisionsOf<TypeParam>(s),
              (std::vector<D>{
                  {kHit, 0}, {kTir, 0}, {kHit, -1}, {kHit, 0}, {kTir, 0}, {kHit, -1}, {kHit, 0}}));
}

// The decisions are the tracer's: with opaque balls, one light, no reflection, no
// background-coloured material and no ambient-only lit point, a pixel is exactly the
// background where its ray misses and exactly ambient * diffuse where it is shadowed.
// Checked over every pixel of the seed scene, in both precisions.
TYPED_TEST(RayDecisionsTest, SeedScene_DecisionsMatchTheRenderedPixels) {
    Scene s = test::seedScene(160, 120);
    s.render.maxDepth = 0;
    s.render.precision = std::is_same_v<TypeParam, float> ? Precision::Float : Precision::Double;
    for (Material& m : s.materials) m.checker.reset();  // one diffuse colour per sphere
    const Image image = test::renderImage(s);
    const PreparedScene<TypeParam> p = prepareScene<TypeParam>(s);
    std::vector<Decision> d;
    int misses = 0, shadowed = 0;
    for (int y = 0; y < s.render.height; ++y)
        for (int x = 0; x < s.render.width; ++x) {
            pixelDecisions(p, x, y, d);
            ASSERT_EQ(d[0].kind, kHit);
            const float* px = image.pixel(x, y);
            if (d[0].value < 0) {
                ++misses;
                ASSERT_EQ(d.size(), 1u);
                for (int c = 0; c < 3; ++c) ASSERT_EQ(px[c], float(TypeParam(s.background[c])));
                continue;
            }
            ASSERT_EQ(d.size(), 2u);
            ASSERT_EQ(d[1].kind, kShadow);
            const Material& m = s.materials[findMaterial(s, s.spheres[d[0].value].material)];
            bool ambientOnly = true;
            for (int c = 0; c < 3; ++c)
                ambientOnly &= px[c] == float(TypeParam(s.ambient[c]) * TypeParam(m.diffuse[c]));
            if (d[1].value) {
                ++shadowed;
                ASSERT_TRUE(ambientOnly) << "pixel " << x << ", " << y << " is lit";
            }
        }
    EXPECT_GT(misses, 1000);   // the sky above the horizon
    EXPECT_GT(shadowed, 200);  // the balls' shadows on the floor
}

TEST(DecisionSignature, EachKindHashesItsOwnSequence) {
    const std::vector<D> a{{kHit, 0}, {kShadow, 1}, {kTir, 0}, {kHit, -1}};
    std::vector<D> b = a;
    EXPECT_EQ(signatureOf(a), signatureOf(b));
    EXPECT_NE(signatureOf(a).hits, 0u);
    b[1].value = 0;  // only the shadow hash changes
    EXPECT_EQ(signatureOf(a).hits, signatureOf(b).hits);
    EXPECT_NE(signatureOf(a).shadows, signatureOf(b).shadows);
    EXPECT_EQ(signatureOf(a).tir, signatureOf(b).tir);
    // Order and length count.
    EXPECT_NE(signatureOf({{kHit, 0}, {kHit, 1}}).hits, signatureOf({{kHit, 1}, {kHit, 0}}).hits);
    EXPECT_NE(signatureOf({{kHit, 0}}).hits, signatureOf({{kHit, 0}, {kHit, 0}}).hits);
}

TEST(FirstDifference, ReportsTheEarliestDifferingDecision) {
    const std::vector<D> base{{kHit, 0}, {kShadow, 0}, {kTir, 0}, {kHit, -1}};
    EXPECT_EQ(firstDifference(base, base), DecisionDifference::None);
    EXPECT_EQ(firstDifference(base, {{kHit, 0}, {kShadow, 1}, {kTir, 1}, {kHit, 0}}),
              DecisionDifference::Shadow);
    // Total internal reflection changes the tree below it, but it came first.
    EXPECT_EQ(firstDifference(base, {{kHit, 0}, {kShadow, 0}, {kTir, 1}, {kHit, 0}, {kTir, 1}}),
              DecisionDifference::Tir);
    EXPECT_EQ(firstDifference(base, {{kHit, 1}, {kShadow, 0}}), DecisionDifference::Hit);
    EXPECT_EQ(firstDifference(base, {{kHit, 0}, {kShadow, 0}}), DecisionDifference::Hit);
}

}  // namespace
}  // namespace whitted
