// What whitted-render says of a render to a quality (--quality,
// --target-psnr): on stderr, the plan's choices and what the render reached;
// in --stats, the same as a "quality" block.
#pragma once

#include <nlohmann/json.hpp>

#include "analysis/quality_target.h"
#include "tracer/adaptive_sampling.h"

namespace whitted {

nlohmann::ordered_json qualityJson(const QualityPlan& plan, const AdaptiveOutcome& outcome);

void sayQualityPlan(const QualityPlan& plan);
void sayQualityReached(const QualityPlan& plan, const AdaptiveOutcome& outcome);

}  // namespace whitted
