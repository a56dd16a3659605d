// Camera moves for the editor's mouse and keys, free of Qt so they are tested
// with the core. Each takes a camera and returns the moved one; none changes
// the field of view except zoom(), and all keep the camera valid for
// validateScene() (look_at never equals position, up never parallel to the view).
#pragma once

#include <optional>

#include "scene.h"

namespace whitted {

// Turns the camera around look_at: `yaw` about the camera's up axis, `pitch`
// about its right axis, both in radians; the distance stays. Pitch stops 1 degree
// short of the up axis rather than flipping over it.
Camera orbit(const Camera& c, double yaw, double pitch);

// Slides position and look_at together across the view: `right` and `up` are
// fractions of the distance to look_at, so a drag feels the same at any scale.
Camera pan(const Camera& c, double right, double up);

// Moves towards look_at (factor < 1) or away (factor > 1); the distance never
// falls below 1e-6 of what it was.
Camera dolly(const Camera& c, double factor);

// Walks position and look_at together: `right`, `up`, `forward` as fractions of
// the distance to look_at (W/A/S/D/Q/E).
Camera walk(const Camera& c, double right, double up, double forward);

// Narrows (factor < 1) or widens the vertical field of view, kept in [1, 170] degrees.
Camera zoom(const Camera& c, double factor);

// Looks at the sphere from the current direction, close enough that it fills
// about two thirds of the view's height.
Camera frameSphere(const Camera& c, const Vec3& centre, double radius);

// The sphere seen through image point (x, y), in pixels of the scene's render
// size (x right, y down, continuous: the centre of pixel (i, j) is (i+0.5, j+0.5)),
// or nothing. Uses the tracer's own intersection in double.
std::optional<int> pickSphere(const Scene& scene, double x, double y);

}  // namespace whitted
