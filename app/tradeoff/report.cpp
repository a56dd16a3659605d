#include "report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace whitted::tradeoff {

namespace {

std::string fixed(double v, int decimals) {
    if (std::isinf(v)) return v > 0 ? "∞" : "−∞";
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
    return buffer;
}

std::string milliseconds(double seconds) {
    return seconds < 0.01 ? fixed(seconds * 1000, 2) + " ms" : fixed(seconds * 1000, 1) + " ms";
}

constexpr const char* kTableHead =
    "| spp | depth | precision | scale | time | Mrays/s | RMSE 8-bit | PSNR 8-bit | PSNR linear "
    "| largest (8-bit steps) |\n|---|---|---|---|---|---|---|---|---|---|\n";

std::string row(const TradeoffPoint& p, bool bold) {
    const std::string b = bold ? "**" : "";
    return "| " + b + std::to_string(p.settings.samplesPerPixel) + b + " | " +
           std::to_string(p.settings.maxDepth) + " | " +
           std::string(precisionName(p.settings.precision)) + " | " +
           fixed(p.settings.resolutionScale, 2) + " | " + milliseconds(p.seconds) + " | " +
           fixed(p.mraysPerSecond, 1) + " | " + fixed(p.error.rmseSrgb8, 2) + " | " +
           fixed(p.error.psnrSrgb8, 1) + " dB | " + fixed(p.error.psnrLinear, 1) + " dB | " +
           fixed(p.error.largest, 0) + " |\n";
}

}  // namespace

std::string pointsTable(const std::vector<TradeoffPoint>& points) {
    std::string md = kTableHead;
    for (const TradeoffPoint& p : points) md += row(p, p.pareto);
    return md;
}

std::string sceneSection(const SceneSummary& s) {
    std::ostringstream md;
    md << "## " << s.name << "\n\n";
    if (!s.command.empty())
        md << "Measured" << (s.date.empty() ? "" : " on " + s.date) << " with `" << s.command
           << "`.\n\n";
    md << "![" << s.name << ": error against time](" << s.directory << "/plot.png)\n\n";
    md << "Reference: double, " << s.reference.render.samplesPerPixel << " samples per pixel, max "
       << "depth " << s.reference.render.maxDepth << " (two past the depth beyond which no pixel "
       << "can change by more than 1/1024 of the missing rays' radiance), "
       << s.reference.render.width << "×" << s.reference.render.height << ", rendered in "
       << fixed(s.referenceSeconds, 1) << " s. Every point is compared with it; smaller images "
       << "are compared stretched, as a viewer shows them.\n\n";
    md << "Depth truncation at the scene's own max_depth " << s.sceneDepth
       << ": the largest cut-off weight is " << fixed(s.truncation, 4)
       << (s.truncation == 0.0f ? " (raising the depth changes nothing)" : "") << "; ";
    if (s.depthWithinTolerance >= kMaxDepth)
        md << "it stays above 1/1024 somewhere up to max_depth " << kMaxDepth
           << " (rays trapped in glass keep their weight). ";
    else
        md << "from max_depth " << s.depthWithinTolerance
           << " on it is below 1/1024 everywhere, so deeper renders change nothing visible. ";
    md << "The reference and the truncation map (black: nothing cut off; white: the largest "
          "weight):\n\n| reference | truncation at max_depth "
       << s.sceneDepth << " |\n|---|---|\n| ![reference](" << s.directory
       << "/reference.png) | ![truncation map](" << s.directory << "/truncation.png) |\n\n";
    md << "The Pareto front (no other point is both faster and more accurate); every point is "
       << "in [table.md](" << s.directory << "/table.md) and [points.csv](" << s.directory
       << "/points.csv).\n\n";
    std::vector<TradeoffPoint> front;
    for (const TradeoffPoint& p : s.points)
        if (p.pareto) front.push_back(p);
    std::sort(front.begin(), front.end(),
              [](const TradeoffPoint& a, const TradeoffPoint& b) { return a.seconds < b.seconds; });
    md << kTableHead;
    for (const TradeoffPoint& p : front) md << row(p, false);
    md << "\n";
    if (!s.curve.empty()) {
        md << "The progressive renderer refining the scene (" << s.curve.back().samples
           << " samples per pixel, its own depth and precision):\n\n";
        md << "![" << s.name << ": progressive refinement](" << s.directory
           << "/progressive.png)\n\n";
        md << "| pass | samples | elapsed | RMSE 8-bit | PSNR 8-bit |\n|---|---|---|---|---|\n";
        for (const ProgressiveSample& c : s.curve)
            md << "| " << c.pass << " | " << (c.samples ? std::to_string(c.samples) : "preview")
               << " | " << milliseconds(c.seconds) << " | " << fixed(c.error.rmseSrgb8, 2) << " | "
               << fixed(c.error.psnrSrgb8, 1) << " dB |\n";
        md << "\n";
    }
    return md.str();
}

std::vector<PresetChoice> choosePresets(const std::vector<SceneSummary>& scenes) {
    std::vector<PresetChoice> presets = {{"Draft", 25.0, 1, 0, Precision::Float, {}},
                                         {"Preview", 35.0, 1, 0, Precision::Float, {}},
                                         {"Final", 45.0, 1, 0, Precision::Float, {}}};
    for (PresetChoice& preset : presets)
        for (const SceneSummary& s : scenes) {
            // Float where it reaches the target: float and double give nearly
            // the same images (docs/numerics.md), so a double point that is
            // "fastest" won by timing noise must not make the preset double.
            const TradeoffPoint* fastest = nullptr;
            const TradeoffPoint* fastestDouble = nullptr;
            const TradeoffPoint* best = nullptr;
            for (const TradeoffPoint& p : s.points) {
                if (p.settings.resolutionScale != 1.0) continue;
                if (!best || p.error.psnrSrgb8 > best->error.psnrSrgb8) best = &p;
                if (p.error.psnrSrgb8 < preset.psnrTarget) continue;
                const TradeoffPoint*& slot =
                    p.settings.precision == Precision::Float ? fastest : fastestDouble;
                if (!slot || p.seconds < slot->seconds) slot = &p;
            }
            if (!fastest) fastest = fastestDouble;
            if (!fastest) {
                preset.notReached.push_back(s.name);
                fastest = best;
            }
            if (!fastest) continue;
            preset.samplesPerPixel =
                std::max(preset.samplesPerPixel, fastest->settings.samplesPerPixel);
            preset.maxDepth = std::max(preset.maxDepth, fastest->settings.maxDepth);
            if (fastest->settings.precision == Precision::Double)
                preset.precision = Precision::Double;
        }
    return presets;
}

std::string report(const std::vector<SceneSummary>& scenes, const std::string& command) {
    std::ostringstream md;
    md << "# The speed/accuracy trade, measured\n\n";
    md << "<!-- Generated file: do not edit. -->\n";
    std::vector<std::string> dates;
    for (const SceneSummary& s : scenes)
        if (!s.date.empty() && std::find(dates.begin(), dates.end(), s.date) == dates.end())
            dates.push_back(s.date);
    std::string when;
    for (const std::string& d : dates) when += (when.empty() ? "" : ", ") + d;
    md << "> **Generated** by `whitted-tradeoff` (app/tradeoff/); do not edit by hand. "
          "Regenerate everything with `cmake --build build --target tradeoff-docs`: it measures "
          "each scene with the command given in its section, then writes this page with `"
       << command << "`." << (when.empty() ? "" : " Measured on " + when + " (UTC).")
       << "\n> Machine: the project's shared 2-core VM; times drift 10 to 30 % between runs, so "
          "compare points of one scene (one run), not absolute times across scenes.\n\n";
    md << "Each scene is rendered over a grid of samples per pixel, max_depth, precision and "
          "resolution scale; every point's time is the median of its runs, and its error is "
          "measured against a double-precision reference with many samples and a depth past "
          "the scene's longest chain (core/tradeoff.h). RMSE and PSNR are given for the 8-bit "
          "sRGB image (what a viewer sees, peak 255) and PSNR for the linear image (peak 1); "
          "the largest difference is in 8-bit steps.\n\n";
    const std::vector<PresetChoice> presets = choosePresets(scenes);
    md << "## Presets\n\n";
    md << "Chosen from the measurements below: for each preset, on every scene, the fastest "
          "full-size float point whose 8-bit PSNR reaches the target (a double point only where "
          "no float point does); the preset takes the largest samples and depth among those "
          "points. Full size only, because a preset cannot change the scene's output size.\n\n";
    md << "| preset | target (8-bit PSNR) | samples per pixel | max depth | precision | "
          "not reached on |\n|---|---|---|---|---|---|\n";
    for (const PresetChoice& p : presets) {
        std::string missing;
        for (const std::string& n : p.notReached) missing += (missing.empty() ? "" : ", ") + n;
        md << "| " << p.name << " | " << fixed(p.psnrTarget, 0) << " dB | " << p.samplesPerPixel
           << " | " << p.maxDepth << " | " << precisionName(p.precision) << " | "
           << (missing.empty() ? "—" : missing) << " |\n";
    }
    md << "\nThe editor's presets (core/render_presets.h) are these values.\n\n";
    for (const SceneSummary& s : scenes) md << sceneSection(s);
    return md.str();
}

}  // namespace whitted::tradeoff
