// The pinhole camera of SPEC §1 in the tracer's precision.
#pragma once

#include <cmath>

#include "scene/scene.h"
#include "tracer/sphere_intersect.h"

namespace whitted {

template <typename T>
struct CameraBasis {
    Vec<T> origin;
    Vec<T> forward;  // unit, towards look_at
    Vec<T> right;    // unit, normalize(cross(up, forward)): +x for a camera looking down +z
    Vec<T> up;       // unit, cross(forward, right)
    T tanHalfFov = 1;
    T aspect = 1;  // width / height
    int width = 1, height = 1;
};

// The basis is built in double and rounded once, so float and double renders
// look through the same camera. The scene's camera must be valid (validateScene).
template <typename T>
CameraBasis<T> makeCameraBasis(const Camera& cam, int width, int height) {
    const Vec3 f = glm::normalize(cam.lookAt - cam.position);
    Vec3 r = glm::normalize(glm::cross(glm::normalize(cam.up), f));
    // With up within a small angle a of the view, the cross product keeps only
    // about eps/a of its relative precision, so r leans off perpendicular by as
    // much; one Gram-Schmidt step puts it back to a few eps.
    r = glm::normalize(r - glm::dot(r, f) * f);
    const Vec3 u = glm::cross(f, r);
    CameraBasis<T> b;
    b.origin = Vec<T>(cam.position);
    b.forward = Vec<T>(f);
    b.right = Vec<T>(r);
    b.up = Vec<T>(u);
    b.tanHalfFov = T(std::tan(cam.vfovDegrees * M_PI / 360.0));
    b.aspect = T(double(width) / double(height));
    b.width = width;
    b.height = height;
    return b;
}

// Unit direction through pixel (i, j) at sub-pixel offset (u, v) in [0,1)^2;
// i to the right, j down.
template <typename T>
Vec<T> cameraDirection(const CameraBasis<T>& b, int i, int j, T u, T v) {
    const T x = ((T(i) + u) / T(b.width) * T(2) - T(1)) * b.tanHalfFov * b.aspect;
    const T y = (T(1) - (T(j) + v) / T(b.height) * T(2)) * b.tanHalfFov;
    return glm::normalize(b.forward + x * b.right + y * b.up);
}

// Unit direction through continuous image point (x, y), in pixels (the
// centre of pixel (i, j) is (i + 0.5, j + 0.5)): the editor's picks and moves
// look through the same rays as the render.
template <typename T>
Vec<T> cameraDirectionAt(const CameraBasis<T>& b, T x, T y) {
    const int i = static_cast<int>(std::floor(x)), j = static_cast<int>(std::floor(y));
    return cameraDirection(b, i, j, x - T(i), y - T(j));
}

}  // namespace whitted
