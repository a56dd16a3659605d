// Tests for core/tracer/camera.h: the basis and the pixel-to-direction mapping of SPEC §1.
#include <cmath>

#include <gtest/gtest.h>

#include "tracer/camera.h"

namespace whitted {
namespace {

template <typename T>
class CameraTest : public ::testing::Test {};
using Precisions = ::testing::Types<float, double>;
TYPED_TEST_SUITE(CameraTest, Precisions);

// Tolerance: 1e-6 absolute on unit vectors (float keeps ~6e-8 per component).
constexpr double kTol = 1e-6;

template <typename T>
void expectVec(const Vec<T>& a, const glm::dvec3& e, const char* what) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(double(a[c]), e[c], kTol) << what << "[" << c << "]";
}

TYPED_TEST(CameraTest, LookingDownPlusZ_RightIsPlusXUpIsPlusY) {
    using T = TypeParam;
    Camera cam;
    cam.position = {0, 0, 0};
    cam.lookAt = {0, 0, 10};
    cam.up = {0, 3, 0};  // any length
    const CameraBasis<T> b = makeCameraBasis<T>(cam, 64, 48);
    expectVec(b.forward, {0, 0, 1}, "forward");
    expectVec(b.right, {1, 0, 0}, "right");
    expectVec(b.up, {0, 1, 0}, "up");
    EXPECT_NEAR(double(b.aspect), 64.0 / 48.0, 1e-7);
}

TYPED_TEST(CameraTest, PixelDirections_FollowSpecFormula) {
    using T = TypeParam;
    // vfov 90: tan(45) = 1. Image 4x2: aspect 2. Pixel (i, j) at (u, v) looks through
    // right ((i+u)/4*2-1)*1*2, up (1-(j+v)/2*2)*1, at 1 along forward.
    Camera cam;
    cam.position = {1, 2, 3};
    cam.lookAt = {1, 2, 4};  // forward +z
    cam.vfovDegrees = 90;
    const CameraBasis<T> b = makeCameraBasis<T>(cam, 4, 2);
    struct Case {
        int i, j;
        double u, v;
        glm::dvec3 plane;  // (right, up, 1)
    };
    const Case cases[] = {
        {0, 0, 0.0, 0.0, {-2, 1, 1}},              // top-left corner of the image
        {3, 1, 0.999, 0.999, {1.999, -0.999, 1}},  // near bottom-right corner
        {1, 0, 0.5, 0.5, {-0.5, 0.5, 1}},          // ((1.5/4)*2-1)*2 = -0.5, 1-0.5 = 0.5
        {2, 1, 0.0, 0.0, {0, 0, 1}},               // the image centre
        {3, 0, 0.5, 0.25, {1.5, 0.75, 1}},
    };
    for (const Case& c : cases) {
        const Vec<T> d = cameraDirection(b, c.i, c.j, T(c.u), T(c.v));
        expectVec(d, glm::normalize(c.plane), "direction");
    }
}

TYPED_TEST(CameraTest, TiltedCamera_BasisIsOrthonormalAndRightIsCrossUpForward) {
    using T = TypeParam;
    // The seed camera: from (0,0.35,-1) to (0,0.25,0): forward (0,-0.1,1)/|.|.
    Camera cam;
    cam.position = {0, 0.35, -1};
    cam.lookAt = {0, 0.25, 0};
    cam.vfovDegrees = 73.74;
    const CameraBasis<T> b = makeCameraBasis<T>(cam, 640, 480);
    const glm::dvec3 f = glm::normalize(glm::dvec3{0, -0.1, 1});
    const glm::dvec3 r = glm::normalize(glm::cross(glm::dvec3{0, 1, 0}, f));
    expectVec(b.forward, f, "forward");
    expectVec(b.right, r, "right");
    expectVec(b.up, glm::cross(f, r), "up");
    EXPECT_NEAR(double(b.up.y), 1 / std::sqrt(1.01), kTol);  // tilted back by the view
    EXPECT_NEAR(double(b.tanHalfFov), std::tan(73.74 * M_PI / 360), 1e-6);
}

TYPED_TEST(CameraTest, CameraLookingDownMinusZ_HasPlusXOnTheLeft) {
    using T = TypeParam;
    // Turned around, right = cross(up, forward) = cross(+y, -z) = -x.
    Camera cam;
    cam.position = {0, 0, 5};
    cam.lookAt = {0, 0, 0};
    const CameraBasis<T> b = makeCameraBasis<T>(cam, 10, 10);
    expectVec(b.right, {-1, 0, 0}, "right");
}

}  // namespace
}  // namespace whitted
