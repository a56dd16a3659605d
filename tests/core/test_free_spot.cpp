// Where Add puts a new sphere (core/scene/free_spot.h): at the point the
// camera looks at unless a sphere is there, else beside it, as the user sees it.
#include <gtest/gtest.h>

#include <algorithm>

#include <glm/geometric.hpp>

#include "scene/free_spot.h"
#include "scene/scene_io.h"
#include "support/test_support.h"

namespace whitted {
namespace {

// The seed's camera: at z = -1 looking along +z, so +x is to the right.
Scene emptyScene() {
    Scene s;
    s.camera.position = {0.0, 0.0, -1.0};
    s.camera.lookAt = {0.0, 0.0, 2.0};
    return s;
}

Sphere ball(const Vec3& centre, double radius) {
    Sphere s;
    s.center = centre;
    s.radius = radius;
    return s;
}

// How far into the nearest sphere a sphere at `centre` of `radius` reaches.
double deepestOverlap(const Scene& scene, const Vec3& centre, double radius) {
    double deepest = -1e30;
    for (const Sphere& s : scene.spheres)
        deepest = std::max(deepest, s.radius + radius - glm::distance(s.center, centre));
    return deepest;
}

TEST(FreeSpot, NothingThere_TheLookAtPoint) {
    const Scene s = emptyScene();
    EXPECT_EQ(freeSpotForSphere(s, 0.5), s.camera.lookAt);
}

TEST(FreeSpot, ASphereAtTheLookAtPoint_OneStepToTheRight) {
    Scene s = emptyScene();
    s.spheres.push_back(ball(s.camera.lookAt, 0.5));
    const Vec3 at = freeSpotForSphere(s, 0.5);
    EXPECT_NEAR(at.x, 1.1, 1e-12);  // 2.2 radii: clear of it, with a gap
    EXPECT_EQ(at.y, s.camera.lookAt.y);
    EXPECT_EQ(at.z, s.camera.lookAt.z);
}

TEST(FreeSpot, RightTaken_TheLeft) {
    Scene s = emptyScene();
    s.spheres.push_back(ball(s.camera.lookAt, 0.5));
    s.spheres.push_back(ball(s.camera.lookAt + Vec3{1.1, 0.0, 0.0}, 0.3));
    EXPECT_NEAR(freeSpotForSphere(s, 0.5).x, -1.1, 1e-12);
}

// The shipped scenes' balls rest on a floor sphere, a little sunk: that is no
// reason to move.
TEST(FreeSpot, SunkALittleIntoTheFloor_StaysPut) {
    Scene s = emptyScene();
    s.spheres.push_back(ball({0.0, -99999.5, 0.0}, 99999.0));  // top at y = -0.5
    s.camera.lookAt = {0.0, -0.05, 2.0};                       // a ball of 0.5 sinks 0.05
    EXPECT_EQ(freeSpotForSphere(s, 0.5), s.camera.lookAt);
}

TEST(FreeSpot, NowhereFreeAlongTheView_TheLookAtPoint) {
    Scene s = emptyScene();
    s.spheres.push_back(ball(s.camera.lookAt, 100.0));
    EXPECT_EQ(freeSpotForSphere(s, 0.5), s.camera.lookAt);
}

// glass.json looks at a point inside its big glass ball, where a new clear
// glass sphere could not be seen.
TEST(FreeSpot, GlassScene_BesideTheBigGlassBall_TouchingNothingButTheFloor) {
    const Scene s = loadScene(WHITTED_SCENES_DIR "/glass.json");
    ASSERT_GT(deepestOverlap(s, s.camera.lookAt, 0.5), kSinkShare * 0.5)
        << "the look-at point is taken";
    const Vec3 at = freeSpotForSphere(s, 0.5);
    EXPECT_NE(at, s.camera.lookAt);
    EXPECT_LE(deepestOverlap(s, at, 0.5), kSinkShare * 0.5);
    EXPECT_EQ(at.y, s.camera.lookAt.y) << "moved across the view, not up or down";
}

}  // namespace
}  // namespace whitted
