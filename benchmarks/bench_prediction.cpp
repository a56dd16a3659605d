// Predictions for scenes never measured (issue 15, item 3): for each shipped
// scene and two generated fields, at four settings, the PSNR, rays and
// seconds predictRender() expects against what the render then measures
// (PSNR against a converged render: double, 512 samples, depth 14). The
// seconds three ways: the rays at the throughput of the render before (the
// settings above in the table; the first row of a scene has the probes'
// own), at that of a one-sample render at the same depth and precision, and
// predictRender()'s own, from its timed probes (speed_probe.h), which the
// editor shows. The last column also gives the render's measured seconds.
// Usage: bench_prediction [WIDTH HEIGHT] (default 320 240). Prints a Markdown table.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "analysis/quality_check.h"
#include "analysis/render_prediction.h"
#include "scene/scene_io.h"
#include "sphere_field.h"

using namespace whitted;

namespace {

struct Named {
    std::string name;
    Scene scene;
};

Named field(int count, std::uint32_t seed) {
    FieldOptions o;
    o.count = count;
    o.seed = seed;
    o.halfWidth = 4.0;
    o.depth = 10.0;
    return {"generated: " + std::to_string(count) + " balls, seed " + std::to_string(seed),
            sphereField(o)};
}

std::vector<Named> scenes(int width, int height) {
    std::vector<Named> list;
    for (const char* name :
         {"seed", "glass", "mirrors", "coloured-shadows", "whitted-1980", "field"})
        list.push_back({name, loadScene(std::string(WHITTED_SCENES_DIR "/") + name + ".json")});
    list.push_back(field(150, 31));
    list.push_back(field(400, 57));
    for (Named& n : list) {
        n.scene.render.width = width;
        n.scene.render.height = height;
        n.scene.render.precision = Precision::Float;
    }
    return list;
}

}  // namespace

int main(int argc, char** argv) {
    const int width = argc > 2 ? std::atoi(argv[1]) : 320;
    const int height = argc > 2 ? std::atoi(argv[2]) : 240;
    std::printf(
        "| scene | spp, depth | PSNR predicted | measured | off by | rays predicted / "
        "measured | seconds predicted / measured | same depth | probes' speed |\n"
        "|---|---|---|---|---|---|---|---|---|\n");
    int within = 0, total = 0, raysWithin = 0, secondsWithin = 0, sameDepthWithin = 0,
        probedWithin = 0;
    for (const Named& n : scenes(width, height)) {
        const Image reference = convergedReference(n.scene);
        double secondsPerRay = 0.0;  // of the render before: none yet
        for (const auto& [spp, depth] : {std::pair{1, 2}, {4, 3}, {16, 5}, {128, 8}}) {
            Scene s = n.scene;
            s.render.samplesPerPixel = spp;
            s.render.maxDepth = depth;
            const RenderPrediction p = predictRender(s);
            const FixedCheck m = checkFixed(s, reference);
            const double off = p.psnrDb - m.error.psnrSrgb8;
            const double rays = p.rays / m.rays;
            if (secondsPerRay == 0.0) secondsPerRay = p.probeSeconds / p.probeRays;
            const double seconds = p.rays * secondsPerRay / m.seconds;
            secondsPerRay = m.seconds / m.rays;
            Scene oneSample = s;
            oneSample.render.samplesPerPixel = 1;
            const FixedCheck one = checkFixed(oneSample, reference);
            const double sameDepth = p.rays * (one.seconds / one.rays) / m.seconds;
            sameDepthWithin += std::fabs(sameDepth - 1.0) <= 0.25;
            const double probed = p.seconds / m.seconds;
            probedWithin += std::fabs(probed - 1.0) <= 0.25;
            ++total;
            within += std::fabs(off) <= 2.0;
            raysWithin += std::fabs(rays - 1.0) <= 0.25;
            secondsWithin += std::fabs(seconds - 1.0) <= 0.25;
            std::printf(
                "| %s | %d, %d | %.1f dB (depth %.3g, float %.3g, samples %.3g codes^2; "
                "slope %.2f) | %.1f dB | %+.1f | %.2f | %.2f | %.2f | %.2f (%.3f s) |\n",
                n.name.c_str(), spp, depth, p.psnrDb, p.depthMse, p.precisionMse, p.samplingMse,
                p.samplingSlope, m.error.psnrSrgb8, off, rays, seconds, sameDepth, probed,
                m.seconds);
            std::fflush(stdout);
        }
    }
    std::printf(
        "\nPSNR within 2 dB: %d of %d; rays within 25%%: %d; seconds within 25%%: %d, "
        "from a same-depth render: %d, from the probes' speed: %d\n",
        within, total, raysWithin, secondsWithin, sameDepthWithin, probedWithin);
}
