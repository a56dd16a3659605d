// What a render to Draft costs beyond the one-sample preset's render, part by
// part, on the shipped scenes at 320x240 (docs/design/performance.md):
//   BM_DraftPlan/SCENE      planQuality() for Draft: the probe renders
//   BM_DraftRender/SCENE    the adaptive render of that plan: the centres, their
//                           estimate, and the tiles it samples again
//   BM_OneSample/SCENE      a fixed render of one sample at the plan's depth:
//                           the centres alone
//   BM_CentreEstimate/SCENE centreSampleEstimate() of every tile of the centres
//   BM_Srgb8Row             srgbEncode8() over a 320x240 picture's values
// Run: build/bin/bench_draft --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// "CPU" is the whole process's, over the render's threads: on a shared machine
// it moves less than the wall time, which waits for the slower thread at every
// pass. Compare rows of one run.
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

#include "analysis/quality_target.h"
#include "image/srgb.h"
#include "scene/scene_io.h"
#include "tracer/adaptive_sampling.h"
#include "tracer/renderer.h"

namespace {

using namespace whitted;

constexpr const char* kScenes[] = {"seed", "glass", "mirrors", "field"};

Scene benchScene(const std::string& name) {
    Scene scene = loadScene(std::string(WHITTED_SCENES_DIR "/") + name + ".json");
    scene.render.width = 320;
    scene.render.height = 240;
    scene.render.precision = Precision::Float;
    return scene;
}

void draftPlan(benchmark::State& state, const std::string& name) {
    const Scene scene = benchScene(name);
    for (auto _ : state) benchmark::DoNotOptimize(planQuality(scene, draftQuality()).maxDepth);
}

void draftRender(benchmark::State& state, const std::string& name, bool adaptive) {
    Scene scene = benchScene(name);
    RenderOptions options = oneShotOptions();
    const QualityPlan plan = planQuality(scene, draftQuality());
    applyPlan(plan, scene, options);
    if (!adaptive) {
        scene.render.samplesPerPixel = 1;
        options = oneShotOptions();
    }
    for (auto _ : state) benchmark::DoNotOptimize(render(scene, options).image.rgb.data());
}

void centreEstimate(benchmark::State& state, const std::string& name) {
    Scene scene = benchScene(name);
    scene.render.samplesPerPixel = 1;
    const Image centres = render(scene, oneShotOptions()).image;
    for (auto _ : state) {
        double mse = 0.0;
        for (int y = 0; y < centres.height; y += kAdaptiveTileEdge)
            for (int x = 0; x < centres.width; x += kAdaptiveTileEdge)
                mse += centreSampleEstimate(centres, {x, y, kAdaptiveTileEdge, kAdaptiveTileEdge})
                           .mse();
        benchmark::DoNotOptimize(mse);
    }
}

void BM_Srgb8Row(benchmark::State& state) {
    std::mt19937 random(1);
    std::uniform_real_distribution<float> value(0.0f, 1.0f);
    std::vector<float> linear(320 * 240 * 3);
    for (float& v : linear) v = value(random) * value(random);  // more of them dark, as in renders
    std::vector<std::uint8_t> codes(linear.size());
    for (auto _ : state) {
        srgbEncode8(linear.data(), linear.size(), codes.data());
        benchmark::DoNotOptimize(codes.data());
    }
    state.SetItemsProcessed(state.iterations() * std::int64_t(linear.size()));
}
BENCHMARK(BM_Srgb8Row)->Unit(benchmark::kMicrosecond);

void registerSceneBenchmarks() {
    for (const char* scene : kScenes) {
        const std::string s = scene;
        auto add = [&](const std::string& name, auto fn, auto... args) {
            benchmark::RegisterBenchmark((name + "/" + s).c_str(), fn, s, args...)
                ->Unit(benchmark::kMillisecond)
                ->MeasureProcessCPUTime()
                ->UseRealTime();
        };
        add("BM_DraftPlan", draftPlan);
        add("BM_DraftRender", draftRender, true);
        add("BM_OneSample", draftRender, false);
        add("BM_CentreEstimate", centreEstimate);
    }
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    registerSceneBenchmarks();
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
