// The benchmarks' large scene: the seed's materials, light, camera and floor
// with `count` small balls scattered in front of the camera (fixed seed: every
// run the same scene, so every run writes the same file).
#pragma once

#include <random>
#include <string>

#include "scene/scene_io.h"

namespace whitted::bench {

inline Scene bigScene(int count) {
    Scene s = loadScene(WHITTED_SCENES_DIR "/seed.json");
    const Sphere floor = s.spheres.back();
    s.spheres.clear();
    s.spheres.reserve(size_t(count) + 1);
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> x(-50, 50), y(0, 5), z(2, 100), r(0.05, 0.3);
    const char* materials[] = {"blue", "purple", "white"};
    for (int i = 0; i < count; ++i)
        s.spheres.push_back(
            {"ball " + std::to_string(i), {x(rng), y(rng), z(rng)}, r(rng), materials[i % 3]});
    s.spheres.push_back(floor);
    return s;
}

}  // namespace whitted::bench
