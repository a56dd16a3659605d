// Spheres sharing a material, and the copy that "Make unique" gives one of them.
#pragma once

#include <string>
#include <string_view>

#include "scene/scene.h"

namespace whitted::ui {

// How many spheres use the material named `material`.
int spheresUsing(const Scene& scene, std::string_view material);

// A material name no material has, numbered after `name`: "blue" gives
// "blue 2" (or "blue 3" when that is taken), "blue 2" gives "blue 3".
std::string numberedMaterialName(const Scene& scene, const std::string& name);

// Gives sphere `sphere` its own copy of its material, named numberedMaterialName;
// the other spheres keep the original. Does nothing to a sphere that is gone.
void makeMaterialUnique(Scene& scene, int sphere);

}  // namespace whitted::ui
