// Whole-scene similarity transforms, for the numerics tests, the sweep program
// and the extreme example scenes: the picture stays the same, only the numbers
// the tracer must cope with change.
#pragma once

#include "scene/scene.h"

namespace whitted {

// Every length times `factor` (> 0): positions, look_at, radii, checker sizes.
// The camera's direction, up and field of view are unchanged.
Scene scaledScene(const Scene& scene, double factor);

// Every position and look_at moved by `offset`. The checker pattern moves with
// the scene only when each component of the offset is a whole multiple of
// twice every checker size.
Scene translatedScene(const Scene& scene, const Vec3& offset);

}  // namespace whitted
