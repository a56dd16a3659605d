// A quality plan in words: why it chose its depth and its samples, the
// target, and what a render reached (plan.why, --stats, the status bar).
#pragma once

#include <string>

#include "analysis/quality_target.h"

namespace whitted::planning {

// plan.why: the depth and why, float against double where the scene is in
// float, the samples, and where the depth and float alone cut off more than
// the target's MSE `total` allows, that it cannot be met.
std::string planWhy(const QualityPlan& plan, bool inFloat, double total);

}  // namespace whitted::planning
