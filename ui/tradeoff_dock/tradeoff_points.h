// The points of the Trade-off dock and how they are named: renders compared
// with the pinned image, and Measure's grid (core's TradeoffPoint).
#pragma once

#include <QString>

#include <cstdint>
#include <optional>
#include <vector>

#include "analysis/tradeoff.h"
#include "image/image_error.h"
#include "scene/scene.h"

namespace whitted::ui {

// A finished render compared with the pinned image.
struct PinnedPoint {
    quint64 id = 0;          // the order points were added in, from 1
    quint64 generation = 0;  // the render's generation (RenderWorker)
    RenderSettings settings;
    double seconds = 0.0;  // the render's wall time in the editor
    std::uint64_t rays = 0;
    std::optional<ErrorStats> error;  // empty while being measured, or when skipped
    QString note;                     // why it was skipped; empty otherwise
};

// "16 spp d3 float" (and " ½" for a Measure point at half size): plot labels.
QString shortLabel(const TradeoffPoint& p);
QString shortLabel(const PinnedPoint& p);
// Several lines: settings, size, time, rays, errors.
QString pointTooltip(const TradeoffPoint& p);
QString pointTooltip(const PinnedPoint& p);
}  // namespace whitted::ui
