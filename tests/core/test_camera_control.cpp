// The editor's camera moves (core/camera_control.*) with hand-checked numbers.
#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "camera/camera_control.h"
#include "camera/view_projection.h"
#include "scene/scene_io.h"
#include "tracer/camera.h"
#include "tracer/tracer.h"

namespace whitted {
namespace {

constexpr double kPi = 3.14159265358979323846;

Camera frontCamera() {
    return Camera{{0, 0, -5}, {0, 0, 0}, {0, 1, 0}, 60};
}

// 100 x 100 pixels through frontCamera(): a unit sphere at the origin and one behind it.
Scene twoOnTheAxis() {
    Scene s;
    s.camera = frontCamera();
    s.render.width = 100;
    s.render.height = 100;
    s.materials = {Material{"m", {1, 1, 1}, 0, 50, 0, 0, 1.5, std::nullopt}};
    s.spheres = {Sphere{"far", {0, 0, 10}, 1, "m"}, Sphere{"near", {0, 0, 0}, 1, "m"}};
    return s;
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
    const Scene s = twoOnTheAxis();
    EXPECT_EQ(pickSphere(s, 50, 50), 1);  // the nearer of the two on the axis
    // tan(30 deg) * 5 = 2.89 half-height at the near sphere: x = 95 is 2.6 units
    // to the right, outside both spheres.
    EXPECT_EQ(pickSphere(s, 95, 50), std::nullopt);
}

// The seed-like view: the eye 5 units from the origin, 100 x 100 pixels.
ImagePoint imageOf(const Camera& c, const Vec3& p) {
    const auto image = projectToImage(c, 100, 100, p);
    EXPECT_TRUE(image.has_value());
    return image.value_or(ImagePoint{-1, -1});
}

TEST(CameraControl, OrbitAboutTurnsTheCameraAroundThePivotWhichStaysInThePicture) {
    // The pivot off the view's axis: a surface point to the right of look_at.
    const Vec3 pivot{1, 0.5, 1};
    const Camera before = frontCamera();
    const ImagePoint pivotBefore = imageOf(before, pivot);
    const Camera after = orbitAbout(before, pivot, 0.3, 0.2);
    const ImagePoint pivotAfter = imageOf(after, pivot);
    EXPECT_NEAR(pivotAfter.x, pivotBefore.x, 1e-9);
    EXPECT_NEAR(pivotAfter.y, pivotBefore.y, 1e-9);
    EXPECT_NEAR(glm::length(after.position - pivot), glm::length(before.position - pivot), 1e-12);
    // A positive pitch raises the eye, as the Up arrow does.
    EXPECT_GT(after.position.y, before.position.y);
    // About look_at it is the old orbit: a quarter turn of yaw from -z to -x.
    expectNear(orbitAbout(before, before.lookAt, kPi / 2, 0).position, {-5, 0, 0});
}

TEST(CameraControl, OrbitAboutStopsOneDegreeShortOfLookingStraightDown) {
    const Camera c = orbitAbout(frontCamera(), {0, 0, 0}, 0, 10.0);
    const Vec3 forward = glm::normalize(c.lookAt - c.position);
    EXPECT_NEAR(std::acos(-forward.y) * 180 / kPi, 1.0, 1e-9);
    EXPECT_FALSE(validateScene(Scene{c, {}, {}, {}, {}, {}, {}}).has_value());
}

TEST(CameraControl, DollyTowardKeepsTheTargetInPlaceAndNeverReachesIt) {
    const Vec3 target{1, -0.5, 2};
    const Camera before = frontCamera();
    const Camera half = dollyToward(before, target, 0.5);
    EXPECT_NEAR(glm::length(half.position - target), glm::length(before.position - target) / 2,
                1e-12);
    const ImagePoint a = imageOf(before, target), b = imageOf(half, target);
    EXPECT_NEAR(a.x, b.x, 1e-9);
    EXPECT_NEAR(a.y, b.y, 1e-9);
    expectNear(half.lookAt - half.position, before.lookAt - before.position);  // same direction
    // A thousand wheel ticks in: still in front of the target, never through it.
    Camera c = before;
    for (int i = 0; i < 1000; ++i) c = dollyToward(c, target, 0.9);
    EXPECT_GT(glm::dot(target - c.position, before.lookAt - before.position), 0.0);
    EXPECT_GT(glm::length(dollyToward(before, target, 0.0).position - target), 0.0);
}

TEST(CameraControl, ProjectToImageInvertsTheCameraRays) {
    Camera c{{0.3, 1.2, -4}, {0.1, 0.4, 0}, {0, 1, 0}, 45};
    const CameraBasis<double> b = makeCameraBasis<double>(c, 160, 90);
    for (const auto& [i, j] : {std::pair{0, 0}, {159, 89}, {80, 45}, {17, 60}}) {
        const Vec3 p = b.origin + cameraDirection(b, i, j, 0.25, 0.75) * 7.0;
        const auto image = projectToImage(c, 160, 90, p);
        ASSERT_TRUE(image.has_value());
        EXPECT_NEAR(image->x, i + 0.25, 1e-9);
        EXPECT_NEAR(image->y, j + 0.75, 1e-9);
    }
    EXPECT_FALSE(projectToImage(c, 160, 90, c.position - (c.lookAt - c.position)).has_value());
}

TEST(CameraControl, SphereOutlineIsTheCircleOfItsAngularRadius) {
    // Radius 1 at distance 5: seen under asin(1/5); vfov 60 puts tan(30 deg) at
    // half the image's 100 pixels, so the outline is a circle of
    // 50 * tan(asin(0.2)) / tan(30 deg) = 17.68 pixels around the centre.
    const auto outline = sphereOutline(frontCamera(), 100, 100, {0, 0, 0}, 1);
    ASSERT_EQ(outline.size(), 1u);
    const double expected = 50 * std::tan(std::asin(0.2)) / std::tan(kPi / 6);
    for (const ImagePoint& p : outline.front())
        EXPECT_NEAR(glm::length(p - ImagePoint{50, 50}), expected, 1e-9);
    EXPECT_EQ(outline.front().front(), outline.front().back());                  // closed
    EXPECT_TRUE(sphereOutline(frontCamera(), 100, 100, {0, 0, -5}, 1).empty());  // eye inside
    // The seed's floor from one unit above it: only its horizon, in pieces, and
    // every piece across the image near its middle row.
    Camera above{{0, 0.5, -3}, {0, 0.5, -2}, {0, 1, 0}, 60};
    const auto horizon = sphereOutline(above, 100, 100, {0, -99999.5, 0}, 99999);
    ASSERT_FALSE(horizon.empty());
    for (const auto& piece : horizon) {
        for (const ImagePoint& p : piece) {
            if (p.x > 0 && p.x < 100) {
                EXPECT_NEAR(p.y, 50, 2);
            }
        }
    }
}

TEST(CameraControl, PickSurfaceGivesThePointOnTheNearestSphere) {
    const Scene s = twoOnTheAxis();
    const auto pick = pickSurface(s, 50, 50);
    ASSERT_TRUE(pick.has_value());
    EXPECT_EQ(pick->sphere, 1);
    expectNear(pick->point, {0, 0, -1}, 1e-12);
}

// Looking through the spheres being moved: the one behind them is picked.
TEST(CameraControl, PickSurfaceLooksThroughTheIgnoredSpheres) {
    const Scene s = twoOnTheAxis();
    const auto pick = pickSurface(s, 50, 50, {1});
    ASSERT_TRUE(pick.has_value());
    EXPECT_EQ(pick->sphere, 0);
    EXPECT_FALSE(pickSurface(s, 50, 50, {0, 1}).has_value());
}

// The pick tests only the spheres near the ray; it must answer exactly as the
// tracer's intersection over the whole scene does, ties and nested spheres included.
TEST(CameraControl, PickSurfaceEqualsTheWholeSceneIntersection) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coord(-3, 3), size(0.05, 1.5);
    Scene s;
    s.camera = Camera{{0, 1, -8}, {0, 0, 0}, {0, 1, 0}, 50};
    s.render.width = 40;
    s.render.height = 30;
    s.materials = {Material{"m", {1, 1, 1}, 0, 50, 0, 0, 1.5, std::nullopt}};
    s.spheres.push_back(Sphere{"floor", {0, -99999.5, 0}, 99999, "m"});
    for (int k = 0; k < 300; ++k)
        s.spheres.push_back(Sphere{"s", {coord(rng), coord(rng), coord(rng)}, size(rng), "m"});
    s.spheres.push_back(s.spheres[5]);  // an exact duplicate: the first one wins the tie
    const PreparedScene<double> whole = prepareScene<double>(s);
    int hits = 0;
    for (int j = 0; j < s.render.height; ++j)
        for (int i = 0; i < s.render.width; ++i) {
            const Ray<double> ray{whole.camera.origin,
                                  cameraDirection(whole.camera, i, j, 0.5, 0.5), -1, false, true};
            const auto expected = closestHit(whole, ray);
            const auto pick = pickSurface(s, i + 0.5, j + 0.5);
            ASSERT_EQ(pick.has_value(), expected.has_value()) << i << ", " << j;
            if (!pick) continue;
            ++hits;
            EXPECT_EQ(pick->sphere, expected->sphere) << i << ", " << j;
            expectNear(pick->point, whole.frameOrigin + ray.origin + ray.dir * expected->t, 0.0);
        }
    EXPECT_GT(hits, 600);
}

}  // namespace
}  // namespace whitted
