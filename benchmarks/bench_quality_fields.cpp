// Rendering to Preview and Final on generated fields that nothing was tuned
// on: other counts, spreads and seeds than test_quality_target's
// and bench_quality's. For each render: the depth chosen, the largest error
// the plan's probe showed for it, and what the render measured against a
// converged reference (double, 512 samples, kDeepReferenceDepth). Where a
// target is missed, the render's worst pixel is examined: what the chosen
// depth cuts off there, at the picture's size with 64 samples, what the
// probe's pixel centre over it showed, and how far the reference itself moves
// there over its last eight levels.
// A large cut where the probe showed none is a feature too small for the
// probe to see; a reference that moves is not converged there.
// Usage: bench_quality_fields [FIRST LAST [WIDTH]] (default 1 8 160; the
// height is three quarters of the width). Prints a Markdown table.
// WHITTED_REFERENCE_CACHE=DIR keeps the references in DIR (core/analysis/reference_cache.h);
// WHITTED_NO_WHY=1 leaves out the examination of a missed target's worst
// pixel (whyMissed(), half a minute a miss at 640x480).
//
// bench_quality_fields depths SEED [SAMPLES [DEEPEST]] (default 8 samples,
// depth 24, 160x120) prints how far the field's picture is from converging
// in depth: each depth against the one before, the same sample positions in
// both, so the difference is the depth's alone, and the seconds each took.
//
// bench_quality_fields presets FIRST LAST [WIDTH] (default 160) times Draft,
// Preview and Final on those fields against the fixed presets
// (render_presets.h), in pairs (paired_times.h): where the preset meets the
// target, against the preset; where it misses, against the fixed setting
// that would meet it, the fewest samples a pixel (a power of two up to 256)
// meeting it at the preset's depth or at the depth ours chose, whichever
// took less time.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <utility>

#include "analysis/quality_check.h"
#include "analysis/reference_cache.h"
#include "base/elapsed.h"
#include "image/image_compare.h"
#include "image/image_error.h"
#include "paired_times.h"
#include "sphere_field.h"
#include "tracer/renderer.h"

using namespace whitted;
using namespace whitted::bench;

namespace {

Scene field(int seed, int width) {
    Scene scene = sphereField(untunedField(seed));
    scene.render.width = width;
    scene.render.height = width * 3 / 4;
    return scene;
}

Image fieldReference(const Scene& scene, int seed) {
    return cachedReference(scene, "field" + std::to_string(seed));
}

// As a plan's checks render: pruned as the render to the plan is.
Image renderAt(Scene scene, int depth, int samples) {
    scene.render.maxDepth = depth;
    scene.render.samplesPerPixel = samples;
    RenderOptions options = oneShotOptions();
    options.pruneBelowWeight = kQualityPruneWeight;
    return render(scene, options).image;
}

struct Pixel {
    int x = 0, y = 0;
    double codes = 0.0;
};

double codesAt(const Image& a, const Image& b, int x, int y) {
    return 255.0 * displayDifference(a.pixel(x, y), b.pixel(x, y));
}

Pixel worstPixel(const Image& image, const Image& reference) {
    Pixel worst;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const double d = codesAt(image, reference, x, y);
            if (d > worst.codes) worst = {x, y, d};
        }
    return worst;
}

// How far the reference moved at pixel (x, y) over its last eight levels
// (kDeepReferenceDepth, the deepest SPEC allows), in double with 256 samples,
// pruned as the reference is: where light trapped in glass is still coming
// out, the reference is not converged there, and it may be the reference
// that is off.
constexpr int kShallowerThanTheReference = kDeepReferenceDepth - 8;

double referenceMovesAt(const Scene& scene, int x, int y) {
    auto at = [&](int depth) { return convergedReference(scene, 256, depth, {{x, y, 1, 1}}); };
    return codesAt(at(kShallowerThanTheReference), at(kDeepReferenceDepth), x, y);
}

// What the chosen depth cuts off at the render's worst pixel, with samples at
// the picture's size, what the probe's centre over that pixel showed, and how
// far the reference there is from converged.
std::string whyMissed(const Scene& scene, const QualityCheck& c, const Image& reference) {
    const QualityPlan& p = c.plan;
    const Pixel worst = worstPixel(c.image, reference);
    const double cut = codesAt(renderAt(scene, p.maxDepth, 64),
                               renderAt(scene, p.referenceDepth, 64), worst.x, worst.y);
    Scene probe = scene;
    probe.render.width = p.probeWidth;
    probe.render.height = p.probeHeight;
    const int px = worst.x * p.probeWidth / scene.render.width;
    const int py = worst.y * p.probeHeight / scene.render.height;
    const double atCentre =
        codesAt(renderAt(probe, p.maxDepth, 1), renderAt(probe, p.referenceDepth, 1), px, py);
    char text[300];
    std::snprintf(text, sizeof text,
                  "pixel (%d, %d): depth %d against %d there %.0f codes at 64 samples, "
                  "%.0f at the probe's centre; the reference, depth %d against %d there: %.0f",
                  worst.x, worst.y, p.maxDepth, p.referenceDepth, cut, atCentre,
                  kShallowerThanTheReference, kDeepReferenceDepth,
                  referenceMovesAt(scene, worst.x, worst.y));
    return text;
}

int printDepthSeries(int seed, int samples, int deepest) {
    Scene scene = field(seed, 160);
    scene.render.precision = Precision::Double;
    std::printf("seed %d, %zu balls, %d samples a pixel, 160x120, double\n", seed,
                scene.spheres.size() - 1, samples);
    std::printf("| depth | against the one before: PSNR, largest | seconds |\n|---|---|---|\n");
    Image before;
    for (int depth : {14, 16, 19, 24, 29, 34}) {
        if (depth > deepest) break;
        const auto start = std::chrono::steady_clock::now();
        const Image image = renderAt(scene, depth, samples);
        const double seconds = secondsSince(start);
        if (before.width == 0) {
            std::printf("| %d | | %.2f |\n", depth, seconds);
        } else {
            const ErrorStats e = measureError(image, before);
            std::printf("| %d | %.1f dB, %.1f codes | %.2f |\n", depth, e.psnrSrgb8, e.largest,
                        seconds);
        }
        std::fflush(stdout);
        before = image;
    }
    return 0;
}

// The fixed setting that would meet the target where the preset does not:
// the fewer seconds of the fewest samples meeting it at the preset's depth
// and at `ourDepth`; samples 0 where neither meets it up to 256.
std::pair<FixedCheck, int> fixedThatWouldMeet(const Scene& scene, const QualityTarget& target,
                                              int presetDepth, int ourDepth,
                                              const Image& reference) {
    std::pair<FixedCheck, int> best{
        fewestFixedSamplesMeeting(scene, target, presetDepth, reference), presetDepth};
    if (ourDepth == presetDepth) return best;
    const FixedCheck atOurs = fewestFixedSamplesMeeting(scene, target, ourDepth, reference);
    if (atOurs.samples > 0 && (best.first.samples == 0 || atOurs.seconds < best.first.seconds))
        best = {atOurs, ourDepth};
    return best;
}

struct PresetTally {
    int presetMet = 0, oursNoSlower = 0;   // where the preset meets the target
    int presetMissed = 0, fixedFound = 0;  // where it does not
    int oursMetWherePresetMissed = 0, oursNoSlowerThanFound = 0;
};

void presetRow(int seed, const Scene& scene, const QualityTarget& target,
               const RenderPreset& preset, const Image& reference, PresetTally& tally) {
    const QualityCheck c = checkQuality(scene, target, reference);
    const Scene fixedScene = withPreset(scene, preset);
    const FixedCheck fixed = checkFixed(fixedScene, reference);
    const bool presetMeets = meetsTarget(fixed.error, target);
    std::printf(
        "| seed %d, %zu balls | %s | %d%s, %.1f spp: %.1f dB, %.0f codes, %s | %.1f dB, "
        "%.0f codes, %s | ",
        seed, scene.spheres.size() - 1, target.name.c_str(), c.plan.maxDepth,
        c.plan.depthShort ? "*" : "", c.meanSamples, c.error.psnrSrgb8, c.error.largest,
        c.met ? "met" : "**missed**", fixed.error.psnrSrgb8, fixed.error.largest,
        presetMeets ? "met" : "**missed**");
    if (presetMeets) {
        const PairedTimes t =
            pairedTimes(scene, target, fixedScene, reference, c.seconds, fixed.seconds, 3, 2.0);
        ++tally.presetMet;
        tally.oursNoSlower += c.met && t.ratio <= 1.0;
        std::printf("%.3f s against %.3f s: %.2f (%d) | |\n", t.ours, t.fixed, t.ratio, t.pairs);
        return;
    }
    ++tally.presetMissed;
    tally.oursMetWherePresetMissed += c.met;
    const auto [would, depth] =
        fixedThatWouldMeet(scene, target, preset.maxDepth, c.plan.maxDepth, reference);
    if (would.samples == 0) {
        std::printf(" | none up to 256 spp at depth %d or %d |\n", preset.maxDepth,
                    c.plan.maxDepth);
        return;
    }
    Scene wouldScene = scene;
    wouldScene.render.samplesPerPixel = would.samples;
    wouldScene.render.maxDepth = depth;
    const PairedTimes t =
        pairedTimes(scene, target, wouldScene, reference, c.seconds, would.seconds, 3, 2.0);
    ++tally.fixedFound;
    tally.oursNoSlowerThanFound += c.met && t.ratio <= 1.0;
    std::printf(" | %d spp, depth %d: %.3f s against ours %.3f s: %.2f (%d) |\n", would.samples,
                depth, t.fixed, t.ours, t.ratio, t.pairs);
}

int printPresets(int first, int last, int width) {
    std::printf(
        "%dx%d, float; reference: double, 512 spp, depth %d; ours includes planning; "
        "times are medians of pairs, ratios ours over fixed\n\n",
        width, width * 3 / 4, kDeepReferenceDepth);
    std::printf(
        "| field | target | ours: depth, mean spp, measured | preset | time against the "
        "preset | where it misses: the fixed setting that would meet it |\n"
        "|---|---|---|---|---|---|\n");
    const QualityTarget targets[] = {draftQuality(), previewQuality(), finalQuality()};
    PresetTally tally;
    for (int seed = first; seed <= last; ++seed) {
        const Scene scene = field(seed, width);
        const Image reference = fieldReference(scene, seed);
        for (int i = 0; i < 3; ++i)
            presetRow(seed, scene, targets[i], kRenderPresets[std::size_t(i)], reference, tally);
        std::fflush(stdout);
    }
    std::printf(
        "\nThe preset met its target in %d renders; ours met it too and was no slower in %d.\n",
        tally.presetMet, tally.oursNoSlower);
    std::printf(
        "The preset missed in %d; ours met %d of those; a fixed setting up to 256 spp met "
        "it in %d; ours met it and was no slower than that in %d.\n",
        tally.presetMissed, tally.oursMetWherePresetMissed, tally.fixedFound,
        tally.oursNoSlowerThanFound);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 2 && std::strcmp(argv[1], "depths") == 0)
        return printDepthSeries(std::atoi(argv[2]), argc > 3 ? std::atoi(argv[3]) : 8,
                                argc > 4 ? std::atoi(argv[4]) : 24);
    if (argc > 3 && std::strcmp(argv[1], "presets") == 0)
        return printPresets(std::atoi(argv[2]), std::atoi(argv[3]),
                            argc > 4 ? std::atoi(argv[4]) : 160);
    const int first = argc > 2 ? std::atoi(argv[1]) : 1;
    const int last = argc > 2 ? std::atoi(argv[2]) : 8;
    const int width = argc > 3 ? std::atoi(argv[3]) : 160;
    std::printf("| field | target | depth | probe's largest | measured | met | why missed |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    int renders = 0, met = 0, psnrMet = 0, promised = 0, promisedMet = 0;
    for (int seed = first; seed <= last; ++seed) {
        const Scene scene = field(seed, width);
        const Image reference = fieldReference(scene, seed);
        for (const QualityTarget& target : {previewQuality(), finalQuality()}) {
            const QualityCheck c = checkQuality(scene, target, reference);
            ++renders;
            met += c.met;
            psnrMet += c.error.psnrSrgb8 >= target.psnrDb;
            promised += !c.plan.depthShort;
            promisedMet += !c.plan.depthShort && c.met;
            std::printf(
                "| seed %d, %zu balls | %s | %d%s | %.1f codes | %.1f dB, %.1f codes | %s | %s |\n",
                seed, scene.spheres.size() - 1, target.name.c_str(), c.plan.maxDepth,
                c.plan.depthShort ? "*" : "", c.plan.depthLargest, c.error.psnrSrgb8,
                c.error.largest, c.met ? "yes" : "**no**",
                c.met || std::getenv("WHITTED_NO_WHY") ? ""
                                                       : whyMissed(scene, c, reference).c_str());
            std::fflush(stdout);
        }
    }
    std::printf("\n%d of %d renders met their target (%dx%d; * no depth up to the cap fits)\n", met,
                renders, width, width * 3 / 4);
    std::printf("%d of %d met the target's PSNR (the largest error aside)\n", psnrMet, renders);
    std::printf(
        "%d of the %d plans that promised their target met it; %d of the %d that said "
        "beforehand it may be missed (*) met it\n",
        promisedMet, promised, met - promisedMet, renders - promised);
}
