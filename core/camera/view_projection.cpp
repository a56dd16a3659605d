#include "camera/view_projection.h"

#include <cmath>

#include <glm/common.hpp>

#include <glm/geometric.hpp>

#include "tracer/camera.h"

namespace whitted {

namespace {

std::optional<ImagePoint> projectWith(const CameraBasis<double>& b, int width, int height,
                                      const Vec3& p) {
    const Vec3 d = p - b.origin;
    const double depth = glm::dot(d, b.forward);
    // A point on or behind the eye's plane has no image (its direction leaves the view).
    if (!(depth > 1e-12 * glm::length(d))) return std::nullopt;
    const double x = glm::dot(d, b.right) / depth / (b.tanHalfFov * b.aspect);
    const double y = glm::dot(d, b.up) / depth / b.tanHalfFov;
    return ImagePoint{(x + 1) / 2 * width, (1 - y) / 2 * height};
}

}  // namespace

std::optional<ImagePoint> projectToImage(const Camera& camera, int width, int height,
                                         const Vec3& p) {
    return projectWith(makeCameraBasis<double>(camera, width, height), width, height, p);
}

std::vector<int> spheresCentredIn(const Camera& camera, int width, int height,
                                  const std::vector<Sphere>& spheres, ImagePoint a, ImagePoint b) {
    const CameraBasis<double> basis = makeCameraBasis<double>(camera, width, height);
    const ImagePoint low = glm::min(a, b), high = glm::max(a, b);
    std::vector<int> inside;
    for (std::size_t i = 0; i < spheres.size(); ++i) {
        const auto p = projectWith(basis, width, height, spheres[i].center);
        if (p && p->x >= low.x && p->x <= high.x && p->y >= low.y && p->y <= high.y)
            inside.push_back(static_cast<int>(i));
    }
    return inside;
}

std::vector<ImagePoint> projectCentres(const Camera& camera, int width, int height,
                                       const std::vector<Sphere>& spheres,
                                       const std::vector<int>& indices) {
    const CameraBasis<double> basis = makeCameraBasis<double>(camera, width, height);
    std::vector<ImagePoint> seen;
    seen.reserve(indices.size());
    for (int i : indices)
        if (const auto p = projectWith(basis, width, height, spheres[i].center)) seen.push_back(*p);
    return seen;
}

std::vector<std::vector<ImagePoint>> sphereOutline(const Camera& camera, int width, int height,
                                                   const Vec3& centre, double radius) {
    const Vec3 toEye = camera.position - centre;
    const double distance = glm::length(toEye);
    if (!(distance > radius)) return {};
    // The lines of sight that touch the sphere touch it on a circle around the
    // axis from the centre to the eye, r^2/d along it, of radius r*sqrt(1-r^2/d^2).
    const Vec3 axis = toEye / distance;
    const double ratio = radius / distance;
    const Vec3 circleCentre = centre + axis * (radius * ratio);
    const double circleRadius = radius * std::sqrt((1 - ratio) * (1 + ratio));
    const Vec3 helper = std::abs(axis.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    const Vec3 u = glm::normalize(glm::cross(axis, helper));
    const Vec3 v = glm::cross(axis, u);

    constexpr int kPoints = 96;
    std::vector<std::optional<ImagePoint>> points;
    for (int k = 0; k < kPoints; ++k) {
        const double a = 2 * M_PI * k / kPoints;
        const Vec3 p = circleCentre + (u * std::cos(a) + v * std::sin(a)) * circleRadius;
        points.push_back(projectToImage(camera, width, height, p));
    }
    // Runs of points in front of the eye; a run through the last point goes on
    // into the first, and a loop with none behind closes on itself.
    std::size_t start = 0;
    while (start < points.size() && points[start]) ++start;
    if (start == points.size()) {
        std::vector<ImagePoint> loop;
        for (const auto& p : points) loop.push_back(*p);
        loop.push_back(loop.front());
        return {loop};
    }
    std::vector<std::vector<ImagePoint>> pieces;
    std::vector<ImagePoint> piece;
    for (std::size_t k = 1; k <= points.size(); ++k) {
        const auto& p = points[(start + k) % points.size()];
        if (p) {
            piece.push_back(*p);
        } else if (!piece.empty()) {
            if (piece.size() > 1) pieces.push_back(piece);
            piece.clear();
        }
    }
    return pieces;
}

}  // namespace whitted
