// Seen from a point light, each sphere fills a cone: a shadow ray can cross
// the sphere only if its direction, towards the light, lies in that cone's
// mirror image. Brute force tests a sphere only for the shadow rays whose
// direction lies in it. Made once a render outside the per-ISA kernels, as
// screen_boxes.h.
#pragma once

#include <vector>

#include "tracer/sphere_set.h"

namespace whitted {

// Shadow rays towards the light with dot(direction, axis) >= cosine may cross
// the sphere; the others miss it, by the sphere test's own reckoning too.
template <typename T>
struct ShadowCone {
    Vec<T> axis;  // unit, from the sphere's centre towards the light
    T cosine;     // -2 where the light is inside the sphere or nearly: every direction
};

// Each sphere's cone from the light at `light`, widened by far more than the
// rounding of a shadow ray's direction and of the sphere test.
template <typename T>
std::vector<ShadowCone<T>> shadowCones(const Vec<T>& light, const SphereSet<T>& spheres);

}  // namespace whitted
