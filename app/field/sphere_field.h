// A field of small matte, mirror and glass balls on the seed's checker floor
// (issue 12): the scene of the scaling benchmark and of `whitted-field`, which
// writes it as a scene file. One generator for both, so the shipped example
// and the benchmark's scene are the same kind of field.
#pragma once

#include <cstdint>

#include "scene/scene.h"

namespace whitted {

struct FieldOptions {
    int count = 1000;        // balls, besides the floor
    std::uint32_t seed = 1;  // std::mt19937 seed: the same options give the same scene
    // Balls rest on the floor with centres in x in [-halfWidth, halfWidth],
    // z in [nearZ, nearZ + depth]; the camera is the seed's, at z = -1.
    double halfWidth = 50.0;
    double nearZ = 1.5;
    double depth = 98.5;
};

// The seed's camera, light, floor and three matte materials, plus "mirror" and
// "glass"; balls of radius 0.05 to 0.3 take the five materials in turn. Max
// depth 5, 1 sample, float, 640x480. Balls may overlap.
Scene sphereField(const FieldOptions& options);

// The same field pictured at width x height: the tests' and benches' fields.
Scene sphereField(const FieldOptions& options, int width, int height);

// bench_quality_fields' field number `n` (issue 15): 40 to 336 balls, other
// counts, spreads and seeds than any the quality targets were tuned on.
FieldOptions untunedField(int n);

}  // namespace whitted
