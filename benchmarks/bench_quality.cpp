// Rendering to a quality (issue 15) on every shipped scene and on a generated
// field: for each preset, the depth and mean samples chosen, the PSNR and
// largest error measured against a converged render (double, 512 samples,
// depth 14), against the fixed preset's settings (render_presets.h) and the
// fewest fixed samples that would meet the target at the chosen depth.
// Usage: bench_quality [WIDTH HEIGHT] (default 320 240). Prints a Markdown table.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "analysis/quality_check.h"
#include "analysis/render_presets.h"
#include "bench_scenes.h"

using namespace whitted;

namespace {

std::vector<NamedScene> scenes(int width, int height) {
    return benchScenes(width, height, {generatedField(300, 7, 5.0, 12.0)});
}

std::string measured(const ErrorStats& e) {
    char text[64];
    std::snprintf(text, sizeof text, "%.1f dB, %.0f codes", e.psnrSrgb8, e.largest);
    return text;
}

void row(const NamedScene& n, const QualityTarget& target, const RenderPreset& preset,
         const Image& reference) {
    const QualityCheck c = checkQuality(n.scene, target, reference);
    Scene fixedScene = n.scene;
    fixedScene.render.samplesPerPixel = preset.samplesPerPixel;
    fixedScene.render.maxDepth = preset.maxDepth;
    const FixedCheck fixed = checkFixed(fixedScene, reference);
    const FixedCheck fewest =
        fewestFixedSamplesMeeting(n.scene, target, c.plan.maxDepth, reference);
    std::printf(
        "| %s | %s | %d%s | %.1f | %s (est. %.1f) | %s | %.2fM, %.3f s (plan %.3f) | %s %s | "
        "%.2fM, %.3f s | ",
        n.name.c_str(), target.name.c_str(), c.plan.maxDepth, c.plan.depthShort ? "*" : "",
        c.meanSamples, measured(c.error).c_str(), c.estimatedPsnr, c.met ? "yes" : "**no**",
        c.rays / 1e6, c.seconds, c.planSeconds, measured(fixed.error).c_str(),
        meetsTarget(fixed.error, target) ? "yes" : "**no**", fixed.rays / 1e6, fixed.seconds);
    if (fewest.samples > 0)
        std::printf("%d spp: %.2fM, %.3f s |\n", fewest.samples, fewest.rays / 1e6, fewest.seconds);
    else
        std::printf("none up to 256 spp |\n");
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    const int width = argc > 2 ? std::atoi(argv[1]) : 320;
    const int height = argc > 2 ? std::atoi(argv[2]) : 240;
    const QualityTarget targets[] = {draftQuality(), previewQuality(), finalQuality()};
    std::printf(
        "%dx%d, float; reference: double, 512 spp, depth 14; rays and seconds of ours "
        "include planning\n\n",
        width, height);
    std::printf(
        "| scene | target | depth | mean spp | measured (estimated dB) | met | ours: "
        "rays, time | fixed preset: measured, met | its rays, time | fewest fixed "
        "samples meeting it at our depth |\n|---|---|---|---|---|---|---|---|---|---|\n");
    for (const NamedScene& n : scenes(width, height)) {
        const Image reference = convergedReference(n.scene);
        for (int i = 0; i < 3; ++i) row(n, targets[i], kRenderPresets[i], reference);
    }
    return 0;
}
