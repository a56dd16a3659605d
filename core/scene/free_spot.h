// Where the editor's Add puts a new sphere: near the point the camera looks
// at, but not inside a sphere already there (on scenes/glass.json that point
// is inside the big glass ball, and a clear-glass sphere added there could not
// be seen).
#pragma once

#include "scene/scene.h"

namespace whitted {

// The spot nearest the camera's look-at point, stepping sideways across the
// view by 2.2 radii at a time (the look-at point first, then right, left,
// further right, ...), where a sphere of `radius` overlaps no
// sphere of the scene by more than kSinkShare of its radius: a ball may rest
// sunk a little into the floor, as the shipped scenes' balls rest on it. The
// look-at point where none of the kSideSteps each way is free. A spot beside
// it is rounded to a thousandth of a unit, as a user would type it.
Vec3 freeSpotForSphere(const Scene& scene, double radius);

inline constexpr double kSinkShare = 0.2;
inline constexpr int kSideSteps = 6;

}  // namespace whitted
