// `whitted-render --inspect X,Y`: one pixel's ray tree as JSON
// (analysis/pixel_ray_tree.h), spheres and lights by name, keys in the order
// a reader wants them (kind first, children last).
#pragma once

#include <nlohmann/json.hpp>

#include "analysis/pixel_ray_tree.h"

namespace whitted {

// {"pixel": [x, y], "value": [r, g, b], "rays": NODE}, each NODE
// {"kind", "origin", "direction", "hit" (a sphere's name or null), "t",
// "weight", "contribution", "children"}, with "depth" and "radiance"; a hit's
// "entering", a transparent hit's "total_internal_reflection", a shadow ray's
// "light" and "transmittance", and "past_depth" where the depth cut rays off.
nlohmann::ordered_json rayTreeJson(const PixelRayTree& tree, const Scene& scene);

}  // namespace whitted
