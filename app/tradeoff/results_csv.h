// One scene's trade-off points as CSV: written by whitted-tradeoff, read back
// by its --report mode to choose the presets across scenes.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "analysis/tradeoff.h"

namespace whitted::tradeoff {

std::string pointsCsv(const std::vector<TradeoffPoint>& points);

// The progressive curve: one line per pass.
std::string progressiveCsv(const std::vector<ProgressiveSample>& curve);

// The points of a CSV written by pointsCsv(). Throws std::runtime_error naming
// the file and line on a malformed row.
std::vector<TradeoffPoint> readPointsCsv(const std::filesystem::path& file);

}  // namespace whitted::tradeoff
