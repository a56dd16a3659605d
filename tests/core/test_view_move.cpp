// Moving an item in the view (core/camera/view_move.*): the grabbed point stays
// under the pointer, axes constrain, the grid snaps; hand-checked numbers.
#include <gtest/gtest.h>

#include "camera/view_move.h"
#include "camera/view_projection.h"

namespace whitted {
namespace {

// 200 x 100 pixels, looking down +z from 10 in front of the origin.
constexpr int kMoveViewWidth = 200, kMoveViewHeight = 100;
const Camera kFacingZ{{0, 0, -10}, {0, 0, 0}, {0, 1, 0}, 60};
// High up and to the side, looking down at the origin: no axis faces it.
const Camera kOblique{{6, 8, -7}, {0, 0.5, 0}, {0, 1, 0}, 45};

ImagePoint seenAt(const Camera& c, const Vec3& p) {
    return *projectToImage(c, kMoveViewWidth, kMoveViewHeight, p);
}

TEST(ViewMove, Free_TheGrabbedPointStaysUnderThePointer) {
    for (const Camera& camera : {kFacingZ, kOblique}) {
        const Vec3 anchor(0.5, 1, 2);
        const ImagePoint from = seenAt(camera, anchor);
        const ImagePoint to = from + ImagePoint(37.25, -12.5);
        const Vec3 moved =
            anchor + viewMoveOffset(camera, kMoveViewWidth, kMoveViewHeight, anchor, from, to, {});
        const ImagePoint now = seenAt(camera, moved);
        EXPECT_NEAR(now.x, to.x, 1e-9);
        EXPECT_NEAR(now.y, to.y, 1e-9);
        // In the plane facing the camera: as far from the eye's plane as before.
        const Vec3 forward = glm::normalize(camera.lookAt - camera.position);
        EXPECT_NEAR(glm::dot(moved - camera.position, forward),
                    glm::dot(anchor - camera.position, forward), 1e-9);
    }
}

TEST(ViewMove, Free_FacingTheCamera_TenPixelsAtDepth10AreTheViewsWidthOverTwenty) {
    // 60 degrees vertical: the plane 10 away is 2 * 10 * tan(30) = 11.547 high,
    // 100 pixels, so a pixel is 0.11547 units: 10 pixels right are 1.1547 along +x.
    const Vec3 offset = viewMoveOffset(kFacingZ, kMoveViewWidth, kMoveViewHeight, {0, 0, 0},
                                       {100, 50}, {110, 50}, {});
    EXPECT_NEAR(offset.x, 20 * std::tan(M_PI / 6) / 10, 1e-12);
    EXPECT_NEAR(offset.y, 0, 1e-12);
    EXPECT_NEAR(offset.z, 0, 1e-12);
}

TEST(ViewMove, Axis_MovesAlongItAloneToWhereThePointerIsNearest) {
    const Vec3 anchor(0, 0, 0);
    const ImagePoint from = seenAt(kOblique, anchor);
    for (int axis : {0, 1, 2}) {
        const Vec3 offset = viewMoveOffset(kOblique, kMoveViewWidth, kMoveViewHeight, anchor, from,
                                           from + ImagePoint(30, 20), axis);
        for (int other : {0, 1, 2}) {
            if (other != axis) {
                EXPECT_EQ(offset[other], 0.0) << axis;
            }
        }
        EXPECT_NE(offset[axis], 0.0) << axis;
    }
    // Along x, seen from the front: x is parallel to the picture, so the item
    // lands exactly under the pointer's column and keeps its row.
    const Vec3 onX =
        viewMoveOffset(kFacingZ, kMoveViewWidth, kMoveViewHeight, anchor, {100, 50}, {130, 70}, 0);
    const ImagePoint now = seenAt(kFacingZ, anchor + onX);
    EXPECT_NEAR(now.x, 130, 1e-9);
    EXPECT_NEAR(now.y, 50, 1e-9);
}

TEST(ViewMove, Axis_AlongTheLineOfSight_DoesNotMove) {
    const Vec3 offset = viewMoveOffset(kFacingZ, kMoveViewWidth, kMoveViewHeight, {0, 0, 0},
                                       {100, 50}, {100, 50}, 2);
    EXPECT_EQ(offset, Vec3(0.0));
}

TEST(ViewMove, RestingCentre_TouchesTheSphereFromOutsideAtThePoint) {
    const Sphere ball{"ball", {1, 2, 3}, 2, "m"};
    const Vec3 top = ball.center + Vec3(0, 2, 0);
    EXPECT_EQ(restingCentre(ball, top, 0.5), Vec3(1, 4.5, 3));
    // The seed's floor: a sphere of radius 99999 whose top is y = -0.5.
    const Sphere floor{"floor", {0, -99999.5, 0}, 99999, "m"};
    const Vec3 onFloor = restingCentre(floor, {0, -0.5, 0}, 0.25);
    EXPECT_NEAR(onFloor.y, -0.25, 1e-9);
}

TEST(ViewMove, SnapToGrid_RoundsEachComponentToTheStep) {
    const Vec3 snapped = snapToGrid({0.123, -0.26, 1.05001}, 0.1);
    EXPECT_NEAR(snapped.x, 0.1, 1e-15);
    EXPECT_NEAR(snapped.y, -0.3, 1e-15);
    EXPECT_NEAR(snapped.z, 1.1, 1e-15);
    EXPECT_EQ(snapToGrid({0.74, 0, 0}, 0.5), Vec3(0.5, 0, 0));
}

// A box drawn over the picture selects the spheres whose centres it holds:
// facing +z from 10 away, 60 degrees high, x = 0 is the image's middle column
// (100) and a centre at x = 1 on the plane z = 0 lies 100 / 11.547 = 8.66
// pixels to its right.
TEST(ViewMove, SpheresCentredIn_TheBoxHoldsTheCentresSeenInsideIt) {
    std::vector<Sphere> spheres = {{"middle", {0, 0, 0}, 0.5, "m"},
                                   {"right", {1, 0, 0}, 0.5, "m"},
                                   {"left", {-1, 0, 0}, 0.5, "m"},
                                   {"behind", {0, 0, -20}, 0.5, "m"}};
    // 100 to 108.5: the middle only; to 108.7: the right one too (8.66 px).
    EXPECT_EQ(spheresCentredIn(kFacingZ, kMoveViewWidth, kMoveViewHeight, spheres, {100, 40},
                               {108.5, 60}),
              std::vector<int>({0}));
    EXPECT_EQ(
        spheresCentredIn(kFacingZ, kMoveViewWidth, kMoveViewHeight, spheres, {108.7, 60}, {95, 40}),
        std::vector<int>({0, 1}));
    // The whole picture: all but the one behind the eye.
    EXPECT_EQ(spheresCentredIn(kFacingZ, kMoveViewWidth, kMoveViewHeight, spheres, {0, 0},
                               {kMoveViewWidth, kMoveViewHeight}),
              std::vector<int>({0, 1, 2}));
}

// The dots of a large selection sit where each sphere's own projection puts
// them, bit for bit; a centre behind the eye has none.
TEST(ViewMove, ProjectCentres_EqualEachProjectionAndSkipThoseBehind) {
    const std::vector<Sphere> spheres = {{"a", {0.3, -0.2, 4}, 0.5, "m"},
                                         {"behind", {12, 15.5, -14}, 0.5, "m"},
                                         {"b", {-2, 1, 9}, 0.5, "m"}};
    const auto seen = projectCentres(kOblique, kMoveViewWidth, kMoveViewHeight, spheres, {0, 1, 2});
    ASSERT_EQ(seen.size(), 2u);
    EXPECT_EQ(seen[0], seenAt(kOblique, spheres[0].center));
    EXPECT_EQ(seen[1], seenAt(kOblique, spheres[2].center));
}

}  // namespace
}  // namespace whitted
