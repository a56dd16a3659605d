// The Markdown of whitted-tradeoff: each scene's table and summary, and
// docs/tradeoff.md with the Draft / Preview / Final presets chosen from the
// measured fronts.
#pragma once

#include <string>
#include <vector>

#include "tradeoff.h"

namespace whitted::tradeoff {

// Every point as a Markdown table, front rows in bold.
std::string pointsTable(const std::vector<TradeoffPoint>& points);

struct SceneSummary {
    std::string name;       // the scene file's stem
    std::string directory;  // relative to the report: where plot.png etc. are
    std::string command;    // the whitted-tradeoff command that measured it
    std::string date;       // when, YYYY-MM-DD (UTC)
    Scene reference;        // the reference's settings
    double referenceSeconds = 0.0;
    int sceneDepth = 0;       // the scene's own max_depth
    float truncation = 0.0f;  // largest cut-off weight at sceneDepth
    int depthWithinTolerance = 0;
    std::vector<TradeoffPoint> points;
    std::vector<ProgressiveSample> curve;
};

// The scene's section of the report (also written alone as summary.md).
std::string sceneSection(const SceneSummary& s);

// A preset: the fastest scale-1 float point of each scene reaching the 8-bit
// PSNR target (double only where no float point does), then the largest
// samples and depth among them.
struct PresetChoice {
    std::string name;
    double psnrTarget = 0.0;
    int samplesPerPixel = 1;
    int maxDepth = 0;
    Precision precision = Precision::Float;
    std::vector<std::string> notReached;  // scenes where no point reached the target
};
std::vector<PresetChoice> choosePresets(const std::vector<SceneSummary>& scenes);

// The whole docs/tradeoff.md.
std::string report(const std::vector<SceneSummary>& scenes, const std::string& command);

}  // namespace whitted::tradeoff
