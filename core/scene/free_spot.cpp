#include "scene/free_spot.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace whitted {

namespace {

bool isFree(const Scene& scene, const Vec3& centre, double radius) {
    for (const Sphere& s : scene.spheres)
        if (glm::distance(s.center, centre) < s.radius + radius - kSinkShare * radius) return false;
    return true;
}

// Across the view, level with the camera's up: sideways as the user sees it.
Vec3 sideways(const Camera& camera) {
    const Vec3 across = glm::cross(camera.up, camera.lookAt - camera.position);
    const double length = glm::length(across);
    return length > 0.0 ? across / length : Vec3{1.0, 0.0, 0.0};
}

// To a thousandth of a unit: the Centre fields then show 1.2, not 1.1998114339.
Vec3 rounded(const Vec3& v) {
    return glm::round(v * 1000.0) / 1000.0;
}

}  // namespace

Vec3 freeSpotForSphere(const Scene& scene, double radius) {
    const Vec3 start = scene.camera.lookAt;
    const Vec3 step = sideways(scene.camera) * (2.2 * radius);
    if (isFree(scene, start, radius)) return start;
    for (int k = 1; k <= kSideSteps; ++k)
        for (const double side : {1.0, -1.0})
            if (const Vec3 at = rounded(start + side * double(k) * step); isFree(scene, at, radius))
                return at;
    return start;
}

}  // namespace whitted
