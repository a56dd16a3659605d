// What max_depth cuts off. For a render at max_depth D, the truncation map holds
// per pixel the summed weight of the rays the tracer did not spawn because they
// would have exceeded D: for each ray of the pixel's tree at depth D that hits a
// reflective or transparent surface, the product of the kr / kt factors along
// its path times the kr + kt it would have passed on (kt going to the reflected
// ray under total internal reflection). A pixel whose weight is 0 cannot change
// if the depth is raised; its weight bounds the share of the pixel's colour
// that the missing rays could have supplied, relative to their radiance.
//
// The tree is walked in double with the tracer's rules (as core/analysis/ray_decisions.h
// does), through the camera ray at each pixel centre.
#pragma once

#include <vector>

#include "image/image.h"
#include "scene/scene.h"
#include "tracer/renderer.h"

namespace whitted {

// Per pixel of the scene's render size, the cut-off weight in all three
// channels. Stops early (leaving the rest 0) when `stop` says so.
Image depthTruncationMap(const Scene& scene, const StopPredicate& stop = {});

// The largest value of a truncation map.
float largestTruncation(const Image& map);

// The deepest max_depth the program chooses by itself for a render that
// follows every ray SPEC spawns (the trade-off tool's reference, a fixed
// setting compared with). Where light is trapped in glass balls the
// truncation does not settle before depth 20 and beyond, and each level
// costs more than the last (a 1-sample render of scenes/field.json: 0.1 s
// at depth 8, 0.7 s at 17, 6.9 s at 25). A render to a quality leaves out
// the rays too light to matter and goes as deep as SPEC allows
// (quality_target.cpp, kDeepestPlanned).
inline constexpr int kDeepestChosen = 16;

// The smallest max_depth (up to kMaxDepth) whose truncation map stays below
// `tolerance` everywhere: past it, raising the depth changes no pixel by more
// than tolerance times the missing rays' radiance. Scenes whose rays bounce
// inside glass without losing weight never get there and return kMaxDepth.
// On a field of thousands of reflective spheres the walk takes many minutes:
// `stop` ends it (returning kMaxDepth), so that a cancelled Measure ends.
int depthWithinTolerance(const Scene& scene, double tolerance = 1.0 / 1024.0,
                         const StopPredicate& stop = {});

}  // namespace whitted
