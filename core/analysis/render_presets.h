// The editor's Draft, Preview and Final render settings, chosen from the
// measured speed/accuracy front (docs/tradeoff.md explains the choice).
#pragma once

#include <array>
#include <string_view>

#include "scene/scene.h"

namespace whitted {

struct RenderPreset {
    std::string_view name;
    int samplesPerPixel;
    int maxDepth;
    Precision precision;
};

// docs/tradeoff.md, 2026-11-22 (cmake --build build --target tradeoff-docs):
// the cheapest full-size settings meeting each preset's targets on every example
// scene. Draft: 20 dB; Preview: 35 dB, no pixel off by more than 64 codes;
// Final: 50 dB, no pixel off by more than 16 codes. Float met every target.
inline constexpr std::array<RenderPreset, 3> kRenderPresets{{
    {"Draft", 1, 2, Precision::Float},
    {"Preview", 16, 5, Precision::Float},
    {"Final", 128, 8, Precision::Float},
}};

}  // namespace whitted
