#include "scene/scene.h"

namespace whitted {

std::string_view precisionName(Precision p) {
    for (const auto& [value, name] : kPrecisionNames)
        if (value == p) return name;
    return "float";
}

std::optional<Precision> parsePrecision(std::string_view name) {
    for (const auto& [value, known] : kPrecisionNames)
        if (known == name) return value;
    return std::nullopt;
}

bool sameSceneContent(const Scene& a, const Scene& b) {
    // Field by field rather than comparing a copy with a's settings: the
    // editor asks on every edit, and a scene may hold 100,000 spheres.
    return a.camera == b.camera && a.background == b.background && a.ambient == b.ambient &&
           a.materials == b.materials && a.lights == b.lights && a.spheres == b.spheres;
}

int findMaterial(const Scene& scene, std::string_view name) {
    for (size_t i = 0; i < scene.materials.size(); ++i)
        if (scene.materials[i].name == name) return static_cast<int>(i);
    return -1;
}

std::unordered_map<std::string_view, int> materialIndices(const Scene& scene) {
    std::unordered_map<std::string_view, int> indices;
    for (size_t i = 0; i < scene.materials.size(); ++i)
        indices.emplace(scene.materials[i].name, static_cast<int>(i));
    return indices;
}

}  // namespace whitted
