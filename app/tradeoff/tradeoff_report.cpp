#include "tradeoff_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <tuple>

namespace whitted::tradeoff {

namespace {

std::string fixed(double v, int decimals) {
    if (std::isinf(v)) return v > 0 ? "∞" : "−∞";
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
    return buffer;
}

std::string milliseconds(double seconds) {
    if (seconds >= 1.0) return fixed(seconds, 2) + " s";
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

// The scene's full-size point with these samples, depth and precision.
const TradeoffPoint* fullSizePoint(const SceneSummary& s, const TradeoffSettings& t) {
    for (const TradeoffPoint& p : s.points)
        if (p.settings.resolutionScale == 1.0 && p.settings.samplesPerPixel == t.samplesPerPixel &&
            p.settings.maxDepth == t.maxDepth && p.settings.precision == t.precision)
            return &p;
    return nullptr;
}

void progressiveSection(std::ostream& md, const SceneSummary& s) {
    md << "The progressive renderer refining the scene (" << s.curve.back().samples
       << " samples per pixel, its own depth and precision):\n\n";
    md << "![" << s.name << ": progressive refinement](" << s.directory << "/progressive.png)\n\n";
    md << "A pass of k samples holds the first k samples of the final pass's pattern "
          "(core/tracer/sampling.h: a sample depends on the count), which cover the pixel less "
          "evenly than a pattern made for k: its error lies above that of a one-shot render "
          "with k samples, the grid's point in the last column, and meets it at the last "
          "pass.\n\n";
    md << "| pass | samples | elapsed | RMSE 8-bit | PSNR 8-bit | one-shot RMSE 8-bit |\n"
          "|---|---|---|---|---|---|\n";
    for (const ProgressiveSample& c : s.curve) {
        const TradeoffPoint* oneShot =
            c.samples ? fullSizePoint(s, {c.samples, s.sceneDepth, s.scenePrecision, 1.0})
                      : nullptr;
        md << "| " << c.pass << " | " << (c.samples ? std::to_string(c.samples) : "preview")
           << " | " << milliseconds(c.seconds) << " | " << fixed(c.error.rmseSrgb8, 2) << " | "
           << fixed(c.error.psnrSrgb8, 1) << " dB | "
           << (oneShot ? fixed(oneShot->error.rmseSrgb8, 2) : "—") << " |\n";
    }
    md << "\n";
}

// Candidates: the full-size settings every scene measured.
std::vector<TradeoffSettings> sharedFullSizeSettings(const std::vector<SceneSummary>& scenes) {
    std::vector<TradeoffSettings> candidates;
    for (const TradeoffPoint& p : scenes.front().points) {
        if (p.settings.resolutionScale != 1.0) continue;
        if (std::all_of(scenes.begin(), scenes.end(), [&](const SceneSummary& s) {
                return fullSizePoint(s, p.settings) != nullptr;
            }))
            candidates.push_back(p.settings);
    }
    return candidates;
}

// Cost: the geometric mean of the setting's times over the scenes, so
// that a scene whose times all drift by a factor (a busier machine
// during its run) cannot change which setting is cheapest.
struct Scored {
    const TradeoffSettings* settings = nullptr;
    double worst = -INFINITY, largest = 0.0, cost = INFINITY;
};

// The preset's setting among the candidates (the rule in report.h); settings null if none.
Scored chooseSetting(const PresetChoice& preset, const std::vector<TradeoffSettings>& candidates,
                     const std::vector<SceneSummary>& scenes) {
    std::vector<Scored> meeting;
    Scored fallback;
    for (const TradeoffSettings& c : candidates) {
        double worst = INFINITY, largest = 0.0, logSum = 0.0;
        for (const SceneSummary& s : scenes) {
            const TradeoffPoint* p = fullSizePoint(s, c);
            worst = std::min(worst, p->error.psnrSrgb8);
            largest = std::max(largest, p->error.largest);
            logSum += std::log(std::max(p->seconds, 1e-9));
        }
        const double cost = std::exp(logSum / scenes.size());
        if (worst >= preset.psnrTarget && largest <= preset.largestLimit)
            meeting.push_back({&c, worst, largest, cost});
        if (worst > fallback.worst || (worst == fallback.worst && cost < fallback.cost))
            fallback = {&c, worst, largest, cost};
    }
    // Settings within kTimingNoise of the cheapest are tied: their order is
    // the machine's mood (1 spp at depth 2 and 3 swapped places between two
    // runs). Of tied settings the smallest wins: fewest samples, then the
    // lowest depth, then float, so the choice does not drift with the noise.
    constexpr double kTimingNoise = 1.25;
    Scored chosen = fallback;
    if (!meeting.empty()) {
        double cheapest = INFINITY;
        for (const Scored& m : meeting) cheapest = std::min(cheapest, m.cost);
        auto smaller = [](const TradeoffSettings& a, const TradeoffSettings& b) {
            return std::tuple(a.samplesPerPixel, a.maxDepth, a.precision != Precision::Float) <
                   std::tuple(b.samplesPerPixel, b.maxDepth, b.precision != Precision::Float);
        };
        chosen = {};
        for (const Scored& m : meeting)
            if (m.cost <= cheapest * kTimingNoise &&
                (!chosen.settings || smaller(*m.settings, *chosen.settings)))
                chosen = m;
    }
    return chosen;
}

void introduction(std::ostream& md, const std::vector<SceneSummary>& scenes,
                  const std::string& command) {
    md << "# The speed/accuracy trade, measured\n\n";
    md << "<!-- Generated file: do not edit. -->\n";
    std::vector<std::string> dates;
    for (const SceneSummary& s : scenes)
        if (!s.date.empty() && std::find(dates.begin(), dates.end(), s.date) == dates.end())
            dates.push_back(s.date);
    std::string when;
    for (const std::string& d : dates) when += (when.empty() ? "" : ", ") + d;
    // The factor of three: the seed's 1024-sample reference at 320x240 took
    // 3.7 s to 11.1 s over four regenerations on one day (2026-11-22).
    md << "> **Generated** by `whitted-tradeoff` (app/tradeoff/); do not edit by hand. "
          "Regenerate everything with `cmake --build build --target tradeoff-docs`: it measures "
          "each scene with the command given in its section, then writes this page with `"
       << command << "`." << (when.empty() ? "" : " Measured on " + when + " (UTC).")
       << "\n> Machine: the project's shared 2-core VM, whose load changes from hour to hour: "
          "times drift 10 to 30 % within a run, and by up to a factor of three between runs "
          "hours apart. Trust the ratios between points of one "
          "scene (one run), not absolute times or times across scenes.\n\n";
    md << "Each scene is rendered over a grid of samples per pixel, max_depth, precision and "
          "resolution scale; every point's time is the median of its runs, and its error is "
          "measured against a double-precision reference with many samples and a depth past "
          "the scene's longest chain (core/analysis/tradeoff.h). RMSE and PSNR are given for the "
          "8-bit "
          "sRGB image (what a viewer sees, peak 255) and PSNR for the linear image (peak 1); "
          "the largest difference is in 8-bit steps.\n\n";
}

void presetTable(std::ostream& md, const std::vector<PresetChoice>& presets) {
    md << "## Presets\n\n";
    md << "These fixed settings are fitted on the scenes below and can miss their targets on "
          "others. `whitted-render --quality draft|preview|final` renders to the target "
          "instead, choosing the depth and the samples for the scene at hand: "
          "[Quality planning](design/quality-planning.md) explains how, and measures both ways on "
          "every shipped "
          "scene and on generated ones.\n\n";
    md << "The rule: for each preset, of the full-size settings (samples per pixel, max depth, "
          "precision) measured on every scene, the cheapest that meets the preset's targets on "
          "every scene: an 8-bit PSNR at least the target, and no pixel further from the "
          "reference than the limit (in 8-bit codes), which the average alone would let through: "
          "a mirror chain cut short is a small area but a large error. Cheapest by the geometric "
          "mean of the setting's times over the scenes, so a scene measured while the machine "
          "was busier (all its times scaled alike) cannot change the choice; settings within "
          "25 % of the cheapest count as tied (timing noise: 1 spp at depth 2 and 3 swapped "
          "places between two runs), and of tied settings the smallest wins (fewest samples, "
          "then the lowest depth, then float). Where no setting "
          "meets a preset's targets on every scene, the one whose worst scene has the best PSNR. "
          "Full size only: a preset does not change the scene's output size. Times are this "
          "run's, at the measured size; they grow with the pixel count.\n\n"
          "- **Draft**, 20 dB, no limit: what one sample per pixel gives once the depth is "
          "enough (edges alias: an RMSE near 25 codes).\n"
          "- **Preview**, 35 dB (RMSE about 4.5 codes), no pixel off by more than 64 codes.\n"
          "- **Final**, 50 dB (RMSE under one code), no pixel off by more than 16 codes.\n\n";
    md << "| preset | targets | samples per pixel | max depth | precision | worst PSNR | "
          "largest error | time (geometric mean) | not met on "
          "|\n|---|---|---|---|---|---|---|---|---|\n";
    for (const PresetChoice& p : presets) {
        std::string missing;
        for (const std::string& n : p.notReached) missing += (missing.empty() ? "" : ", ") + n;
        md << "| " << p.name << " | " << fixed(p.psnrTarget, 0) << " dB"
           << (p.largestLimit < 255.0 ? ", ≤ " + fixed(p.largestLimit, 0) + " codes" : "") << " | "
           << p.samplesPerPixel << " | " << p.maxDepth << " | " << precisionName(p.precision)
           << " | " << fixed(p.worstPsnr, 1) << " dB | " << fixed(p.largest, 0) << " | "
           << milliseconds(p.meanSeconds) << " | " << (missing.empty() ? "—" : missing) << " |\n";
    }
}

void presetsPerScene(std::ostream& md, const std::vector<PresetChoice>& presets,
                     const std::vector<SceneSummary>& scenes) {
    md << "\nEach preset on each scene (time, 8-bit PSNR, largest error in codes):\n\n| preset |";
    for (const SceneSummary& s : scenes) md << " " << s.name << " |";
    md << "\n|---|";
    for (std::size_t i = 0; i < scenes.size(); ++i) md << "---|";
    md << "\n";
    for (const PresetChoice& p : presets) {
        md << "| " << p.name << " |";
        for (const PresetChoice::SceneFigures& f : p.perScene)
            md << " " << milliseconds(f.seconds) << ", " << fixed(f.psnrSrgb8, 1) << " dB, "
               << fixed(f.largest, 0) << " |";
        md << "\n";
    }
}

void presetsAsCode(std::ostream& md, const std::vector<PresetChoice>& presets) {
    md << "\nAs core/analysis/render_presets.h spells them:\n\n```cpp\n"
          "inline constexpr std::array<RenderPreset, 3> kRenderPresets{{\n";
    for (const PresetChoice& p : presets)
        md << "    {\"" << p.name << "\", " << p.samplesPerPixel << ", " << p.maxDepth << ", "
           << (p.precision == Precision::Double ? "Precision::Double" : "Precision::Float")
           << "},\n";
    md << "}};\n```\n\n";
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
    const bool settled =
        s.reference.render.maxDepth >= settledReferenceDepth(s.depthWithinTolerance);
    md << "Reference: double, " << s.reference.render.samplesPerPixel << " samples per pixel, max "
       << "depth " << s.reference.render.maxDepth
       << (settled ? " (two past the depth beyond which no pixel can change by more than 1/1024 "
                     "of the missing rays' radiance), "
                   : " (the deepest a reference goes: deeper, pixels still change by more than "
                     "1/1024 of the missing rays' radiance, but each level costs more than the "
                     "last), ")
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
           << " on it is below 1/1024 everywhere: deeper renders change no pixel by more than "
              "1/1024 of the missing rays' radiance. ";
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
    if (!s.curve.empty()) progressiveSection(md, s);
    return md.str();
}

std::vector<PresetChoice> choosePresets(const std::vector<SceneSummary>& scenes) {
    // Draft: what one sample per pixel gives once the depth is enough (edges
    // alias, so the RMSE stays near 25 codes). Preview: noise faint, and no pixel
    // a quarter of the range off. Final: under one code on average and no pixel
    // more than 16 codes off, which the average alone would let through (a
    // mirror chain cut short is a small area but a large error).
    std::vector<PresetChoice> presets(3);
    presets[0].name = "Draft", presets[0].psnrTarget = 20.0, presets[0].largestLimit = 255.0;
    presets[1].name = "Preview", presets[1].psnrTarget = 35.0, presets[1].largestLimit = 64.0;
    presets[2].name = "Final", presets[2].psnrTarget = 50.0, presets[2].largestLimit = 16.0;
    if (scenes.empty()) return presets;
    const std::vector<TradeoffSettings> candidates = sharedFullSizeSettings(scenes);
    for (PresetChoice& preset : presets) {
        const Scored chosen = chooseSetting(preset, candidates, scenes);
        if (!chosen.settings) continue;
        preset.samplesPerPixel = chosen.settings->samplesPerPixel;
        preset.maxDepth = chosen.settings->maxDepth;
        preset.precision = chosen.settings->precision;
        preset.worstPsnr = chosen.worst;
        preset.largest = chosen.largest;
        preset.meanSeconds = chosen.cost;
        for (const SceneSummary& s : scenes) {
            const TradeoffPoint* p = fullSizePoint(s, *chosen.settings);
            preset.perScene.push_back({s.name, p->seconds, p->error.psnrSrgb8, p->error.largest});
            if (p->error.psnrSrgb8 < preset.psnrTarget || p->error.largest > preset.largestLimit)
                preset.notReached.push_back(s.name);
        }
    }
    return presets;
}

std::string report(const std::vector<SceneSummary>& scenes, const std::string& command,
                   const std::string& quality) {
    std::ostringstream md;
    introduction(md, scenes, command);
    const std::vector<PresetChoice> presets = choosePresets(scenes);
    presetTable(md, presets);
    presetsPerScene(md, presets, scenes);
    presetsAsCode(md, presets);
    md << quality;
    for (const SceneSummary& s : scenes) md << sceneSection(s);
    return md.str();
}

}  // namespace whitted::tradeoff
