#include "camera/view_move.h"

#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "tracer/camera.h"

namespace whitted {

namespace {

// The unit direction of the line of sight through image point p, as the tracer's.
Vec3 sightThrough(const CameraBasis<double>& view, ImagePoint p) {
    return cameraDirectionAt(view, p.x, p.y);
}

// Where the line of sight through p meets the plane through `anchor` facing the camera.
std::optional<Vec3> onViewPlane(const CameraBasis<double>& view, const Vec3& anchor, ImagePoint p) {
    const Vec3 d = sightThrough(view, p);
    const double along = glm::dot(d, view.forward);
    if (!(along > 1e-12)) return std::nullopt;
    return view.origin + d * (glm::dot(anchor - view.origin, view.forward) / along);
}

// How far along `axis` from the anchor the pointer at p is: where its line of
// sight meets the plane that holds the axis and faces the camera most, taken
// back onto the axis. An axis across the view thus follows the pointer's
// column or row exactly, whatever the perspective.
std::optional<double> alongAxis(const CameraBasis<double>& view, const Vec3& anchor,
                                const Vec3& axis, ImagePoint p) {
    const Vec3 normal = view.forward - glm::dot(view.forward, axis) * axis;
    const Vec3 d = sightThrough(view, p);
    const double across = glm::dot(d, normal);
    if (!(glm::length(normal) > 1e-9) || !(std::abs(across) > 1e-12)) return std::nullopt;
    const double t = glm::dot(anchor - view.origin, normal) / across;
    if (!(t > 0)) return std::nullopt;
    return glm::dot(view.origin + d * t - anchor, axis);
}

}  // namespace

Vec3 viewMoveOffset(const Camera& camera, int width, int height, const Vec3& anchor,
                    ImagePoint from, ImagePoint to, std::optional<int> axis) {
    const CameraBasis<double> view = makeCameraBasis<double>(camera, width, height);
    if (axis) {
        Vec3 unit(0.0);
        unit[*axis] = 1;
        const auto start = alongAxis(view, anchor, unit, from);
        const auto end = alongAxis(view, anchor, unit, to);
        if (!start || !end) return Vec3(0.0);
        return unit * (*end - *start);
    }
    const auto start = onViewPlane(view, anchor, from);
    const auto end = onViewPlane(view, anchor, to);
    if (!start || !end) return Vec3(0.0);
    return *end - *start;
}

Vec3 restingCentre(const Sphere& under, const Vec3& surfacePoint, double radius) {
    return surfacePoint + glm::normalize(surfacePoint - under.center) * radius;
}

Vec3 snapToGrid(const Vec3& offset, double step) {
    return glm::round(offset / step) * step;
}

}  // namespace whitted
