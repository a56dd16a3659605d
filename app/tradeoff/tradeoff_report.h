// The Markdown of whitted-tradeoff: each scene's table and summary, and
// docs/tradeoff.md with the Draft / Preview / Final presets chosen from the
// measured fronts.
#pragma once

#include <string>
#include <vector>

#include "analysis/tradeoff.h"
#include "base/printed.h"

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
    int sceneDepth = 0;                           // the scene's own max_depth
    Precision scenePrecision = Precision::Float;  // and precision
    float truncation = 0.0f;                      // largest cut-off weight at sceneDepth
    int depthWithinTolerance = 0;
    std::vector<TradeoffPoint> points;
    std::vector<ProgressiveSample> curve;
};

// The scene's section of the report (also written alone as summary.md).
std::string sceneSection(const SceneSummary& s);

// A preset: of the full-size settings every scene measured, the cheapest (by
// the geometric mean of its times over the scenes) whose 8-bit PSNR reaches
// the target and whose largest pixel error stays within the limit on every
// scene, settings within 25 % of the cheapest tied and the smallest of them
// taken; if none meets the targets, the one whose worst scene has the best PSNR.
struct PresetChoice {
    std::string name;
    double psnrTarget = 0.0;    // dB, 8-bit
    double largestLimit = 0.0;  // largest pixel error allowed, in 8-bit codes
    int samplesPerPixel = 1;
    int maxDepth = 0;
    Precision precision = Precision::Float;
    double worstPsnr = 0.0;    // the lowest 8-bit PSNR of the setting over the scenes
    double largest = 0.0;      // its largest pixel error over the scenes, in codes
    double meanSeconds = 0.0;  // geometric mean of its times over the scenes
    struct SceneFigures {
        std::string scene;
        double seconds = 0.0, psnrSrgb8 = 0.0, largest = 0.0;
    };
    std::vector<SceneFigures> perScene;   // in the order of the scenes
    std::vector<std::string> notReached;  // scenes where it stays below the target
};
std::vector<PresetChoice> choosePresets(const std::vector<SceneSummary>& scenes);

// The whole docs/tradeoff.md; `quality`, if any, after the presets
// (qualitySection()).
std::string report(const std::vector<SceneSummary>& scenes, const std::string& command,
                   const std::string& quality = {});

}  // namespace whitted::tradeoff
