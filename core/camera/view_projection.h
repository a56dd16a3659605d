// Where scene points land in the rendered image: the inverse of the camera's
// ray directions (camera.h), for what the editor draws over the picture
// (selection outline, light markers, the orbit's pivot). Free of Qt.
#pragma once

#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "scene/scene.h"

namespace whitted {

using ImagePoint = glm::dvec2;  // pixels of the render size, x right, y down, continuous

// The image point `p` is seen at, for a camera rendering width x height pixels;
// nothing when p is not in front of the eye.
std::optional<ImagePoint> projectToImage(const Camera& camera, int width, int height,
                                         const Vec3& p);

// The indices of the spheres whose centres are seen inside the image box with
// corners `a` and `b` (any two opposite ones), in ascending order: what a box
// drawn over the picture selects. One camera basis for all: a million spheres
// took 90 ms one projectToImage at a time.
std::vector<int> spheresCentredIn(const Camera& camera, int width, int height,
                                  const std::vector<Sphere>& spheres, ImagePoint a, ImagePoint b);

// Where the centres of spheres `indices` are seen, those in front of the eye
// alone: the dots of a large selection, with one camera basis for all.
std::vector<ImagePoint> projectCentres(const Camera& camera, int width, int height,
                                       const std::vector<Sphere>& spheres,
                                       const std::vector<int>& indices);

// The sphere's outline as the camera sees it (the circle where the eye's lines
// of sight touch it), as polylines in image points: one closed loop when all of
// it is in front of the eye, pieces when part is behind (a huge floor's horizon),
// nothing when the eye is inside the sphere.
std::vector<std::vector<ImagePoint>> sphereOutline(const Camera& camera, int width, int height,
                                                   const Vec3& centre, double radius);

}  // namespace whitted
