// Material presets: named finishes (Matte, Plastic, Mirror, Chrome, Glass,
// Water) as plain data, one table for the editor's Add menu and Preset combo.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "scene/scene.h"

namespace whitted {

// Every shading field of a material except its name and checker pattern (SPEC §3).
struct MaterialPreset {
    std::string_view name;
    Vec3 diffuse;
    double specular;
    double shininess;
    double reflectivity;
    double transparency;
    double ior;
};

// The presets, in the order a menu lists them.
std::span<const MaterialPreset> materialPresets();

// `material` with the preset's finish; its name and checker pattern are kept, so
// applying a preset to the floor keeps it a checkered floor.
Material withPreset(Material material, const MaterialPreset& preset);

// A new material named `name` with the preset's finish.
Material presetMaterial(const MaterialPreset& preset, std::string name);

}  // namespace whitted
