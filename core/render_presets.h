// The editor's Draft, Preview and Final render settings, chosen from the
// measured speed/accuracy front (docs/tradeoff.md explains the choice).
#pragma once

#include <array>
#include <string_view>

#include "scene.h"

namespace whitted {

struct RenderPreset {
    std::string_view name;
    int samplesPerPixel;
    int maxDepth;
    Precision precision;
};

inline constexpr std::array<RenderPreset, 3> kRenderPresets{{
    {"Draft", 1, 2, Precision::Float},
    {"Preview", 4, 4, Precision::Float},
    {"Final", 64, 8, Precision::Double},
}};

}  // namespace whitted
