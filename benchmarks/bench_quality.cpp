// Rendering to a quality on every shipped scene and on a generated
// field: for each preset, the depth and mean samples chosen, the PSNR and
// largest error measured against a converged render (double, 512 samples,
// kDeepReferenceDepth), against the fixed preset's settings
// (render_presets.h) and the fewest fixed samples that would meet the target
// at the chosen depth.
// Where ours and the preset together take under a second, they are timed
// again in pairs (paired_times.h).
// Usage: bench_quality [WIDTH HEIGHT [times [SCENE]]] (default 320 240).
// Prints a Markdown table; `times` prints only the paired times of Draft and
// Preview, of every scene or of the one named (seed, glass, ...).
// WHITTED_REFERENCE_CACHE=DIR keeps the references in DIR (core/analysis/reference_cache.h).
// WHITTED_QUALITY_CSV=FILE also writes the rows to FILE (quality_table.h), for
// `whitted-tradeoff --report --quality-csv` (docs/tradeoff.md).
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "analysis/quality_check.h"
#include "analysis/quality_table.h"
#include "analysis/reference_cache.h"
#include "analysis/render_presets.h"
#include "base/utc_date.h"
#include "bench_scenes.h"
#include "paired_times.h"

using namespace whitted;
using namespace whitted::bench;

namespace {

std::vector<NamedScene> scenes(int width, int height) {
    return benchScenes(width, height, {generatedField(300, 7, 5.0, 12.0)});
}

std::string measured(const ErrorStats& e) {
    char text[64];
    std::snprintf(text, sizeof text, "%.1f dB, %.0f codes", e.psnrSrgb8, e.largest);
    return text;
}

// Where the preset misses the target, ours is timed against the fewest
// fixed samples that meet it at our depth: one run each, as printed.
QualityRow csvRow(const NamedScene& n, const QualityTarget& target, const QualityCheck& c,
                  const FixedCheck& preset, double timeAgainstPreset, const FixedCheck& fewest) {
    QualityRow r{todayUtc(),
                 n.name,
                 n.scene.render.width,
                 n.scene.render.height,
                 target.name,
                 target.psnrDb,
                 target.largestCodes,
                 c.plan.maxDepth,
                 c.plan.depthShort,
                 c.meanSamples,
                 c.error.psnrSrgb8,
                 c.error.largest,
                 c.met,
                 preset.error.psnrSrgb8,
                 preset.error.largest,
                 meetsTarget(preset.error, target),
                 timeAgainstPreset,
                 {},
                 std::nullopt};
    if (r.presetMet) {
        r.fixedMeeting = "the preset";
        r.timeAgainstFixedMeeting = timeAgainstPreset;
    } else if (fewest.samples > 0) {
        r.fixedMeeting = std::to_string(fewest.samples) + " spp";
        r.timeAgainstFixedMeeting = c.seconds / fewest.seconds;
    }
    return r;
}

void row(const NamedScene& n, const QualityTarget& target, const RenderPreset& preset,
         const Image& reference, std::ofstream* csv) {
    const QualityCheck c = checkQuality(n.scene, target, reference);
    const Scene fixedScene = withPreset(n.scene, preset);
    const FixedCheck fixed = checkFixed(fixedScene, reference);
    const PairedTimes times =
        pairedTimes(n.scene, target, fixedScene, reference, c.seconds, fixed.seconds);
    const FixedCheck fewest =
        fewestFixedSamplesMeeting(n.scene, target, c.plan.maxDepth, reference);
    std::printf(
        "| %s | %s | %d%s | %.1f | %s (est. %.1f) | %s | %.2fM, %.3f s (plan %.3f) | %s %s | "
        "%.2fM, %.3f s | %.2f (%d) | ",
        n.name.c_str(), target.name.c_str(), c.plan.maxDepth, c.plan.depthShort ? "*" : "",
        c.meanSamples, measured(c.error).c_str(), c.estimatedPsnr, c.met ? "yes" : "**no**",
        c.rays / 1e6, times.ours, c.planSeconds, measured(fixed.error).c_str(),
        meetsTarget(fixed.error, target) ? "yes" : "**no**", fixed.rays / 1e6, times.fixed,
        times.ratio, times.pairs);
    if (fewest.samples > 0)
        std::printf("%d spp: %.2fM, %.3f s |\n", fewest.samples, fewest.rays / 1e6, fewest.seconds);
    else
        std::printf("none up to 256 spp |\n");
    std::fflush(stdout);
    if (csv) *csv << qualityCsvLine(csvRow(n, target, c, fixed, times.ratio, fewest)) << std::endl;
}

// Only the times of ours and the preset, in pairs (pairedTimes(): at least
// 3, up to 15 or about 4 s), for Draft and Preview. No reference is
// rendered, so it runs at sizes where the references would take an hour;
// the error is measured against the preset's own render and not printed.
void printTimes(int width, int height, const std::vector<NamedScene>& timed) {
    std::printf("%dx%d, float; times of ours include planning; medians of the pairs\n\n", width,
                height);
    std::printf(
        "| scene | target | depth | mean spp | ours (plan) | preset | ours / preset (pairs) "
        "|\n|---|---|---|---|---|---|---|\n");
    const QualityTarget targets[] = {draftQuality(), previewQuality()};
    for (const NamedScene& n : timed) {
        for (int i = 0; i < 2; ++i) {
            const Scene preset = withPreset(n.scene, kRenderPresets[i]);
            const Image presetImage = render(preset, oneShotOptions()).image;
            const QualityCheck c = checkQuality(n.scene, targets[i], presetImage);
            const PairedTimes times =
                pairedTimes(n.scene, targets[i], preset, presetImage, c.seconds,
                            checkFixed(preset, presetImage).seconds, 3, 4.0);
            std::printf("| %s | %s | %d | %.1f | %.4f s (%.4f) | %.4f s | %.2f (%d) |\n",
                        n.name.c_str(), targets[i].name.c_str(), c.plan.maxDepth, c.meanSamples,
                        times.ours, c.planSeconds, times.fixed, times.ratio, times.pairs);
            std::fflush(stdout);
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    const int width = argc > 2 ? std::atoi(argv[1]) : 320;
    const int height = argc > 2 ? std::atoi(argv[2]) : 240;
    if (argc > 3 && std::string(argv[3]) == "times") {
        std::vector<NamedScene> timed = scenes(width, height);
        if (argc > 4) {
            std::string names;
            for (const NamedScene& n : timed) names += (names.empty() ? "'" : ", '") + n.name + "'";
            std::erase_if(timed, [&](const NamedScene& n) { return n.name != argv[4]; });
            if (timed.empty()) {
                std::fprintf(stderr, "bench_quality: no scene is named '%s'; the scenes: %s\n",
                             argv[4], names.c_str());
                return 2;
            }
        }
        printTimes(width, height, timed);
        return 0;
    }
    const QualityTarget targets[] = {draftQuality(), previewQuality(), finalQuality()};
    std::printf(
        "%dx%d, float; reference: double, 512 spp, depth %d; rays and seconds of ours "
        "include planning; times are medians of the pairs counted\n\n",
        width, height, kDeepReferenceDepth);
    std::printf(
        "| scene | target | depth | mean spp | measured (estimated dB) | met | ours: "
        "rays, time | fixed preset: measured, met | its rays, time | time ours / preset "
        "(pairs) | fewest fixed samples meeting it at our depth |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|\n");
    std::ofstream csv;
    if (const char* file = std::getenv("WHITTED_QUALITY_CSV")) {
        csv.open(file);
        if (!csv) {
            std::fprintf(stderr, "bench_quality: %s: cannot write\n", file);
            return 2;
        }
        csv << qualityCsvHeader() << "\n";
    }
    for (const NamedScene& n : scenes(width, height)) {
        const Image reference = cachedReference(n.scene, n.name);
        for (int i = 0; i < 3; ++i)
            row(n, targets[i], kRenderPresets[i], reference, csv.is_open() ? &csv : nullptr);
    }
    return 0;
}
