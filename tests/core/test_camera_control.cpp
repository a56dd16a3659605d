// The editor's camera moves (core/camera_control.*) with hand-checked numbers.
#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "camera_control.h"
#include "scene_io.h"

namespace whitted {
namespace {

constexpr double kPi = 3.14159265358979323846;

Camera frontCamera() {
    return Camera{{0, 0, -5}, {0, 0, 0}, {0, 1, 0}, 60};
}

void expectNear(const Vec3& a, const Vec3& b, double tol = 1e-9) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

TEST(CameraControl, OrbitYawQuarterTurnKeepsDistanceAndLookAt) {
    // 90 degrees about +y takes the camera from -z to -x (right-handed rotation of (0,0,-5)).
    const Camera c = orbit(frontCamera(), kPi / 2, 0);
    expectNear(c.position, {-5, 0, 0});
    expectNear(c.lookAt, {0, 0, 0});
    EXPECT_NEAR(glm::length(c.position - c.lookAt), 5.0, 1e-12);
}

TEST(CameraControl, OrbitPitchStopsOneDegreeShortOfThePole) {
    const Camera c = orbit(frontCamera(), 0, kPi);  // far more than up to the pole
    const Vec3 back = glm::normalize(c.position - c.lookAt);
    EXPECT_NEAR(std::acos(back.y) * 180 / kPi, 1.0, 1e-9);  // 1 degree from +y
    EXPECT_FALSE(validateScene(Scene{c, {}, {}, {}, {}, {}, {}}).has_value());
}

TEST(CameraControl, PanMovesPositionAndLookAtTogetherByFractionsOfTheDistance) {
    const Camera c = pan(frontCamera(), 0.1, -0.2);  // right is +x, up is +y here
    expectNear(c.position, {0.5, -1.0, -5});
    expectNear(c.lookAt, {0.5, -1.0, 0});
}

TEST(CameraControl, DollyScalesTheDistanceAndNeverReachesLookAt) {
    expectNear(dolly(frontCamera(), 0.5).position, {0, 0, -2.5});
    const Camera close = dolly(frontCamera(), 0.0);
    EXPECT_NEAR(glm::length(close.position - close.lookAt), 5e-6, 1e-12);
}

TEST(CameraControl, WalkAndZoom) {
    const Camera w = walk(frontCamera(), 0, 0, 0.2);  // forward 20 % of 5
    expectNear(w.position, {0, 0, -4});
    expectNear(w.lookAt, {0, 0, 1});
    EXPECT_DOUBLE_EQ(zoom(frontCamera(), 0.5).vfovDegrees, 30.0);
    EXPECT_DOUBLE_EQ(zoom(frontCamera(), 100).vfovDegrees, 170.0);
    EXPECT_DOUBLE_EQ(zoom(frontCamera(), 0.001).vfovDegrees, 1.0);
}

TEST(CameraControl, FrameSphereFillsTwoThirdsOfTheHeight) {
    // vfov 60: the sphere's angular radius is 20 degrees, distance r / sin(20 deg).
    const Camera c = frameSphere(frontCamera(), {3, 1, 2}, 0.5);
    expectNear(c.lookAt, {3, 1, 2});
    EXPECT_NEAR(glm::length(c.position - c.lookAt), 0.5 / std::sin(20 * kPi / 180), 1e-12);
    expectNear(glm::normalize(c.lookAt - c.position), {0, 0, 1});  // same view direction
}

TEST(CameraControl, PickFindsTheSphereAtTheImageCentreAndNothingBeside) {
    Scene s;
    s.camera = frontCamera();
    s.render.width = 100;
    s.render.height = 100;
    s.materials = {Material{"m", {1, 1, 1}, 0, 50, 0, 0, 1.5, std::nullopt}};
    s.spheres = {Sphere{"far", {0, 0, 10}, 1, "m"}, Sphere{"near", {0, 0, 0}, 1, "m"}};
    EXPECT_EQ(pickSphere(s, 50, 50), 1);  // the nearer of the two on the axis
    // tan(30 deg) * 5 = 2.89 half-height at the near sphere: x = 95 is 2.6 units
    // to the right, outside both spheres.
    EXPECT_EQ(pickSphere(s, 95, 50), std::nullopt);
}

}  // namespace
}  // namespace whitted
