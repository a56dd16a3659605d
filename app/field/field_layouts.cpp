#include "field_layouts.h"

#include <algorithm>
#include <cmath>

namespace whitted {

namespace {

// Four balls a square unit, over a square that grows with the count: the
// default field instead keeps its box, so that 1,000,000 balls pile up in it.
FieldOptions uniformAtFixedDensity(int count) {
    FieldOptions o;
    const double side = std::sqrt(double(count) / 4.0);
    o.halfWidth = std::max(1.0, side / 2);
    o.depth = std::max(1.0, side);
    return o;
}

}  // namespace

const std::vector<FieldLayout>& fieldLayouts() {
    static const std::vector<FieldLayout> layouts = {
        {"field", "bench_scaling's field: balls of radius 0.05 to 0.3 in a 100 x 98.5 box"},
        {"uniform", "as many balls a square unit (four) at every count, the box growing"},
        {"clustered", "64 Gaussian clumps (spread 1.5) in the field's box, floating up to 3"},
        {"radii", "radii from 0.01 to 10, each decade as likely, from z = 12"},
        {"glass", "four balls in five glass"},
        {"mirrors", "four balls in five mirrors"},
        {"inside", "the camera in the field's middle, balls floating up to 6 all round"},
        {"above", "the camera high above the field, looking straight down"},
    };
    return layouts;
}

std::vector<std::string> fieldLayoutNames() {
    std::vector<std::string> names;
    for (const FieldLayout& l : fieldLayouts()) names.push_back(l.name);
    return names;
}

std::optional<FieldOptions> fieldLayout(std::string_view name, int count) {
    FieldOptions o;
    if (name == "uniform") {
        o = uniformAtFixedDensity(count);
    } else if (name == "clustered") {
        o.placement = FieldPlacement::clustered;
        o.floatHeight = 3;
    } else if (name == "radii") {
        o.minRadius = 0.01;
        o.maxRadius = 10;
        o.logRadii = true;
        o.nearZ = 12;  // no ball of radius 10 around the camera, at z = -1
    } else if (name == "glass") {
        o.mix = FieldMix::mostlyGlass;
    } else if (name == "mirrors") {
        o.mix = FieldMix::mostlyMirrors;
    } else if (name == "inside") {
        o.view = FieldView::inside;
        o.floatHeight = 6;
    } else if (name == "above") {
        o.view = FieldView::above;
    } else if (name != "field") {
        return std::nullopt;
    }
    o.count = count;
    return o;
}

}  // namespace whitted
