// How the editor says render settings and times, in the Render tab's
// predictions, the presets' tooltips and the Trade-off dock alike.
#pragma once

#include <QString>

#include "scene/scene.h"

namespace whitted::ui {

// "12.5 ms", "1.25 s", "42 s"
QString secondsText(double seconds);
// "float" or "double"
QString precisionText(Precision precision);
// "16 spp, depth 3, float"
QString settingsText(int samples, int depth, Precision precision);
// "16 spp, depth 3, float, 640 × 480"
QString settingsText(const RenderSettings& settings);

}  // namespace whitted::ui
