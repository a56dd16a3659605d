// Moving an item in the editor's view (Blender's G): where the item goes when
// the pointer that grabbed it moves across the picture. Free of Qt.
#pragma once

#include <optional>

#include "camera/view_projection.h"

namespace whitted {

// How far an item at `anchor` moves when the pointer goes from image point
// `from` to `to` (pixels of the render size, as projectToImage gives them).
// Free (no axis): in the plane through the anchor facing the camera, so that
// the point grabbed stays under the pointer. Along world axis `axis` (0 x,
// 1 y, 2 z): as far as the pointer's line of sight meets the plane that holds
// the axis and faces the camera most, so that an axis across the view follows
// the pointer exactly. Zero where that is undefined: an axis along the view,
// a line of sight parallel to the plane or meeting it behind the eye.
Vec3 viewMoveOffset(const Camera& camera, int width, int height, const Vec3& anchor,
                    ImagePoint from, ImagePoint to, std::optional<int> axis);

// The centre of a sphere of `radius` that rests on `under` at `surfacePoint`,
// a point of its surface: touching it there from outside (on the floor, on
// the floor; on a ball, on that ball).
Vec3 restingCentre(const Sphere& under, const Vec3& surfacePoint, double radius);

// The offset with each component rounded to the nearest multiple of `step` (> 0).
Vec3 snapToGrid(const Vec3& offset, double step);

}  // namespace whitted
