// A sphere's box on the screen from the two planes through the eye that hold
// the camera's up (or right) axis and touch the sphere: a ray that meets the
// sphere meets its shadow on the plane of the other two axes, a disc, so the
// ray's slope along each axis lies between those of the disc's two tangents.
#include "tracer/screen_boxes.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace whitted {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kQuarterTurn = M_PI / 2;

// The slopes a/b (b > 0) of directions in the plane (a, b) from the origin
// that come within `reach` of the point (ca, cb).
struct Slopes {
    double low, high;
};
Slopes slopesTowards(double ca, double cb, double reach) {
    const double distance = std::hypot(ca, cb);
    if (distance <= reach) return {-kInf, kInf};
    const double centre = std::atan2(ca, cb);
    const double spread = std::asin(reach / distance);
    const double low = centre - spread, high = centre + spread;
    if (low >= kQuarterTurn || high <= -kQuarterTurn) return {kInf, -kInf};  // behind the eye
    return {low <= -kQuarterTurn ? -kInf : std::tan(low),
            high >= kQuarterTurn ? kInf : std::tan(high)};
}

// Outward to the float at or beyond the double.
float floatBelow(double v) {
    const float f = float(v);
    return double(f) <= v ? f : std::nextafter(f, -std::numeric_limits<float>::infinity());
}
float floatAbove(double v) {
    const float f = float(v);
    return double(f) >= v ? f : std::nextafter(f, std::numeric_limits<float>::infinity());
}

}  // namespace

template <typename T>
std::vector<ScreenBox> sphereScreenBoxes(const CameraBasis<T>& camera,
                                         const SphereSet<T>& spheres) {
    const glm::dvec3 eye(camera.origin), right(camera.right), up(camera.up),
        forward(camera.forward);
    // Image-plane slope to pixels, as the kernel's camera rays make them.
    const double halfWidth = double(camera.tanHalfFov) * double(camera.aspect);
    const double halfHeight = double(camera.tanHalfFov);
    auto column = [&](double slope) { return (slope / halfWidth + 1.0) * camera.width / 2.0; };
    auto row = [&](double slope) { return (1.0 - slope / halfHeight) * camera.height / 2.0; };
    std::vector<ScreenBox> boxes(std::min(spheres.count(), kScreenBoxedSpheres));
    for (std::size_t k = 0; k < boxes.size(); ++k) {
        const glm::dvec3 c = spheres.centreOf(int(k)) - eye;
        const double radius = spheres.radiusOf(int(k));
        const double reach = radius + kSkipWidening * (glm::length(c) + radius);
        const double cf = glm::dot(c, forward);
        const Slopes x = slopesTowards(glm::dot(c, right), cf, reach);
        const Slopes y = slopesTowards(glm::dot(c, up), cf, reach);
        boxes[k] = {floatBelow(column(x.low)), floatAbove(column(x.high)), floatBelow(row(y.high)),
                    floatAbove(row(y.low))};
    }
    return boxes;
}

template std::vector<ScreenBox> sphereScreenBoxes(const CameraBasis<float>&,
                                                  const SphereSet<float>&);
template std::vector<ScreenBox> sphereScreenBoxes(const CameraBasis<double>&,
                                                  const SphereSet<double>&);

}  // namespace whitted
