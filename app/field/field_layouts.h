// Named field layouts, each a stress for the sphere tree that bench_scaling's
// own field is not: whitted-field --layout and bench_scaling --layouts make
// them, and docs/design/acceleration.md times each against Embree.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sphere_field.h"

namespace whitted {

struct FieldLayout {
    std::string name;
    std::string description;  // a line for --help
};

// "field" (bench_scaling's, the default), "uniform", "clustered", "radii",
// "glass", "mirrors", "inside", "above".
const std::vector<FieldLayout>& fieldLayouts();

// Their names, in that order: what --layout accepts.
std::vector<std::string> fieldLayoutNames();

// The layout's options for `count` balls; nullopt for an unknown name.
std::optional<FieldOptions> fieldLayout(std::string_view name, int count);

}  // namespace whitted
