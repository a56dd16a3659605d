// A field of small matte, mirror and glass balls on the seed's checker floor:
// the scene of the scaling benchmark and of `whitted-field`, which writes it
// as a scene file. One generator for both, so the shipped example and the
// benchmark's scenes are the same kind of field.
#pragma once

#include <cstdint>

#include "scene/scene.h"

namespace whitted {

// Where the balls' centres fall in the field's box.
enum class FieldPlacement {
    uniform,    // anywhere in the box, each as likely
    clustered,  // in Gaussian clumps about `clusters` centres spread over the box
};

// Which materials the balls take.
enum class FieldMix {
    even,           // blue, purple, white, mirror and glass in turn
    mostlyGlass,    // four balls in five glass, the fifth one of the other four
    mostlyMirrors,  // four balls in five mirrors, the fifth one of the other four
};

// Where the camera looks from.
enum class FieldView {
    front,   // the seed's camera, at z = -1, looking down the field
    inside,  // at the field's middle, 1.5 above the floor, looking down +z
    above,   // high above the field's middle, looking straight down
};

struct FieldOptions {
    int count = 1000;        // balls, besides the floor
    std::uint32_t seed = 1;  // std::mt19937 seed: the same options give the same scene
    // Centres in x in [-halfWidth, halfWidth], z in [nearZ, nearZ + depth].
    double halfWidth = 50.0;
    double nearZ = 1.5;
    double depth = 98.5;
    FieldPlacement placement = FieldPlacement::uniform;
    int clusters = 64;           // clustered: how many clumps
    double clusterSpread = 1.5;  // clustered: each clump's standard deviation
    double minRadius = 0.05;     // radii from minRadius to maxRadius: uniform, or
    double maxRadius = 0.3;      // log-uniform (each decade as likely) with logRadii
    bool logRadii = false;
    double floatHeight = 0;  // 0: balls rest on the floor; else they float up to this
    FieldMix mix = FieldMix::even;
    FieldView view = FieldView::front;
};

// The seed's light, floor and three matte materials, plus "mirror" and
// "glass"; max depth 5, 1 sample, float, 640x480. Balls may overlap.
Scene sphereField(const FieldOptions& options);

// The same field pictured at width x height: the tests' and benches' fields.
Scene sphereField(const FieldOptions& options, int width, int height);

// bench_quality_fields' field number `n`: 40 to 336 balls, other counts,
// spreads and seeds than any the quality targets were tuned on.
FieldOptions untunedField(int n);

}  // namespace whitted
