// Where single precision stops being right, as measured by the sweep program
// (docs/numerics.md): the editor warns when a float scene lies outside it.
#pragma once

#include <optional>
#include <string>

#include "scene/scene.h"

namespace whitted {

// Why this scene is outside the range in which float renders were measured to
// match double ones, or nothing when it is inside (whatever its precision setting).
std::optional<std::string> floatRangeProblem(const Scene& scene);

}  // namespace whitted
