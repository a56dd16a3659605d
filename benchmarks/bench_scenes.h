// The scenes the quality and prediction benches run on: every shipped scene,
// then generated fields that no choice was fitted on; all at one size, in float.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene_io.h"
#include "sphere_field.h"
#include "tracer/renderer.h"

namespace whitted {

struct NamedScene {
    std::string name;
    Scene scene;
};

// `count` balls of app/field within `halfWidth` of the axis and `depth` deep.
inline NamedScene generatedField(int count, std::uint32_t seed, double halfWidth, double depth) {
    return {"generated: " + std::to_string(count) + " balls, seed " + std::to_string(seed),
            sphereField({.count = count, .seed = seed, .halfWidth = halfWidth, .depth = depth})};
}

inline std::vector<NamedScene> benchScenes(int width, int height,
                                           std::vector<NamedScene> generated) {
    std::vector<NamedScene> list;
    for (const char* name :
         {"seed", "glass", "mirrors", "coloured-shadows", "whitted-1980", "field"})
        list.push_back({name, loadScene(std::string(WHITTED_SCENES_DIR "/") + name + ".json")});
    for (NamedScene& g : generated) list.push_back(std::move(g));
    for (NamedScene& n : list) {
        n.scene.render.width = width;
        n.scene.render.height = height;
        n.scene.render.precision = Precision::Float;
    }
    return list;
}

// The faster of two one-pass renders of the scene: a render the machine's
// other work slowed says less about the settings.
inline RenderResult fasterOfTwo(const Scene& scene) {
    RenderResult best = render(scene, oneShotOptions());
    RenderResult again = render(scene, oneShotOptions());
    return again.seconds < best.seconds ? again : best;
}

}  // namespace whitted
