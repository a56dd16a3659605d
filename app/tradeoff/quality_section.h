// docs/tradeoff.md's section on rendering to a quality: how a
// target becomes settings for the scene at hand, and bench_quality's
// measurements of target against what was met, beside the fixed presets.
#pragma once

#include <string>
#include <vector>

#include "analysis/quality_table.h"

namespace whitted::tradeoff {

// `csvFile` is where the rows came from, as the report names it.
std::string qualitySection(const std::vector<QualityRow>& rows, const std::string& csvFile);

}  // namespace whitted::tradeoff
