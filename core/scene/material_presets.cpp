// The preset table. Whitted's plain sum (SPEC §3) has no Fresnel term and no
// energy normalisation, so each preset keeps diffuse + reflectivity +
// transparency near or below 1: a mirror or glass that also kept a bright
// diffuse colour would look milky (a transparent material with the default
// diffuse 0.8 looks white).
#include "scene/material_presets.h"

#include <array>

namespace whitted {

namespace {

const std::array<MaterialPreset, 6> kPresets{{
    // name      diffuse               ks    n       kr    kt    ior
    {"Matte", {0.8, 0.8, 0.8}, 0.0, 10.0, 0.0, 0.0, 1.5},
    {"Plastic", {0.8, 0.1, 0.1}, 0.6, 80.0, 0.05, 0.0, 1.5},
    {"Mirror", {0.02, 0.02, 0.02}, 1.0, 1000.0, 0.95, 0.0, 1.5},
    {"Chrome", {0.15, 0.15, 0.16}, 0.8, 200.0, 0.75, 0.0, 1.5},
    // Glass and water: almost no diffuse, most light passes; a little reflection.
    {"Glass", {0.02, 0.02, 0.02}, 1.0, 300.0, 0.08, 0.9, 1.5},
    {"Water", {0.01, 0.02, 0.03}, 0.8, 200.0, 0.05, 0.92, 1.33},
}};

}  // namespace

std::span<const MaterialPreset> materialPresets() {
    return kPresets;
}

Material withPreset(Material material, const MaterialPreset& preset) {
    material.diffuse = preset.diffuse;
    material.specular = preset.specular;
    material.shininess = preset.shininess;
    material.reflectivity = preset.reflectivity;
    material.transparency = preset.transparency;
    material.ior = preset.ior;
    return material;
}

Material presetMaterial(const MaterialPreset& preset, std::string name) {
    Material material;
    material.name = std::move(name);
    return withPreset(std::move(material), preset);
}

}  // namespace whitted
