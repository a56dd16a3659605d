#include "panels/material_sharing.h"

#include <algorithm>
#include <cctype>
#include <optional>
#include <utility>

namespace whitted::ui {

int spheresUsing(const Scene& scene, std::string_view material) {
    return static_cast<int>(std::count_if(scene.spheres.begin(), scene.spheres.end(),
                                          [&](const Sphere& s) { return s.material == material; }));
}

namespace {

bool isSpace(char c) {
    return std::isspace(static_cast<unsigned char>(c)) != 0;
}

// "stem N": N the digits after the last space, up to 8 of them, the stem
// before that space ending in something other than a space. Not <regex>:
// GCC 12 warns inside it in the sanitizer builds.
std::optional<std::pair<std::string, int>> stemAndNumber(const std::string& name) {
    const std::size_t space = name.rfind(' ');
    if (space == std::string::npos || space == 0 || isSpace(name[space - 1])) return std::nullopt;
    const std::string digits = name.substr(space + 1);
    if (digits.empty() || digits.size() >= 9) return std::nullopt;
    for (char c : digits)
        if (c < '0' || c > '9') return std::nullopt;
    return std::pair{name.substr(0, space), std::stoi(digits)};
}

}  // namespace

std::string numberedMaterialName(const Scene& scene, const std::string& name) {
    // A copy of "blue 2" is "blue 3", not "blue 2 2".
    std::string stem = name;
    int n = 2;
    if (const auto numbered = stemAndNumber(name)) {
        stem = numbered->first;
        n = numbered->second + 1;
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
