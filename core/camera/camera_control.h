// Camera moves for the editor's mouse and keys, free of Qt so they are tested
// with the core. Each takes a camera and returns the moved one; none changes
// the field of view except zoom(), and all keep the camera valid for
// validateScene() (look_at never equals position, up never parallel to the view).
#pragma once

#include <optional>
#include <vector>

#include "scene/scene.h"

namespace whitted {

// Turns the camera around `pivot`: `yaw` about the camera's up axis, `pitch`
// about its right axis, both in radians. Position and look_at turn together, so
// the pivot stays where it is in the picture and the camera keeps its distance
// to it. A positive pitch raises the eye (it looks down more); the view stops 1
// degree short of straight up or down rather than flipping over.
Camera orbitAbout(const Camera& c, const Vec3& pivot, double yaw, double pitch);

// orbitAbout() look_at.
Camera orbit(const Camera& c, double yaw, double pitch);

// Slides position and look_at together across the view: `right` and `up` are
// fractions of the distance to look_at, so a drag feels the same at any scale.
Camera pan(const Camera& c, double right, double up);

// Moves towards look_at (factor < 1) or away (factor > 1); the distance never
// falls below 1e-6 of what it was.
Camera dolly(const Camera& c, double factor);

// Moves position and look_at together towards `target` (factor < 1) or away
// from it, so the distance to it becomes `factor` times what it was, never less
// than 1e-6 of it: the camera never reaches or passes the target, and the target
// stays where it is in the picture (the wheel zooms towards the cursor).
Camera dollyToward(const Camera& c, const Vec3& target, double factor);

// Walks position and look_at together: `right`, `up`, `forward` as fractions of
// the distance to look_at (W/A/S/D/Q/E).
Camera walk(const Camera& c, double right, double up, double forward);

// Frame `frame` (1 to frames) of a turntable: the eye turned about look_at,
// around the up axis, by frame - 1 of `frames` equal steps of one full turn.
// Frame 1 is the camera itself. A pure function of its arguments, so every
// machine of a farm renders the same frame.
Camera turntableCamera(const Camera& c, int frame, int frames);

// Narrows (factor < 1) or widens the vertical field of view, kept in [1, 170] degrees.
Camera zoom(const Camera& c, double factor);

// Looks at the sphere from the current direction, close enough that it fills
// about two thirds of the view's height.
Camera frameSphere(const Camera& c, const Vec3& centre, double radius);

// What is seen through one image point: the sphere and the point on its surface.
struct SurfacePick {
    int sphere;
    Vec3 point;
};

// The surface seen through image point (x, y), in pixels of the scene's render
// size (x right, y down, continuous: the centre of pixel (i, j) is (i+0.5, j+0.5)),
// or nothing. Uses the tracer's own intersection in double. The spheres at
// `ignored` (ascending indices) are looked through: those being moved.
std::optional<SurfacePick> pickSurface(const Scene& scene, double x, double y,
                                       const std::vector<int>& ignored = {});

// pickSurface()'s sphere.
std::optional<int> pickSphere(const Scene& scene, double x, double y);

}  // namespace whitted
