// What a Measure run of the Trade-off dock left: the grid's points against
// its reference. The dock makes it; the predictions read it (settings_prediction.h).
#pragma once

#include <vector>

#include "analysis/tradeoff.h"
#include "scene/scene.h"

namespace whitted::ui {

struct MeasureResults {
    Scene scene;  // as measured; its render size is scale 1
    std::vector<TradeoffPoint> points;
    int total = 0;           // points in the grid; more than points.size() when cancelled
    bool cancelled = false;  // stopped before the grid was done
    int referenceSamples = 0;
    int referenceDepth = 0;
    double referenceSeconds = 0.0;
    double seconds = 0.0;  // the whole run, reference included
};

}  // namespace whitted::ui
