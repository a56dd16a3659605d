#include "material_sharing.h"

#include <algorithm>
#include <regex>

namespace whitted::ui {

int spheresUsing(const Scene& scene, std::string_view material) {
    return static_cast<int>(std::count_if(scene.spheres.begin(), scene.spheres.end(),
                                          [&](const Sphere& s) { return s.material == material; }));
}

std::string numberedMaterialName(const Scene& scene, const std::string& name) {
    // A copy of "blue 2" is "blue 3", not "blue 2 2".
    static const std::regex numbered(R"(^(.*\S) (\d+)$)");
    std::smatch match;
    std::string stem = name;
    int n = 2;
    if (std::regex_match(name, match, numbered) && match[2].length() < 9) {
        stem = match[1];
        n = std::stoi(match[2]) + 1;
    }
    for (;; ++n) {
        std::string candidate = stem + " " + std::to_string(n);
        if (findMaterial(scene, candidate) < 0) return candidate;
    }
}

void makeMaterialUnique(Scene& scene, int sphere) {
    if (sphere < 0 || sphere >= static_cast<int>(scene.spheres.size())) return;
    const int original = findMaterial(scene, scene.spheres[sphere].material);
    if (original < 0) return;
    Material copy = scene.materials[original];
    copy.name = numberedMaterialName(scene, copy.name);
    scene.spheres[sphere].material = copy.name;
    scene.materials.push_back(std::move(copy));
}

}  // namespace whitted::ui
