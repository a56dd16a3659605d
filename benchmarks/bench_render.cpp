// Render throughput of the seed scene at 1280x720, one-shot, in float and double,
// on one thread and on all cores. Run:
//   build/bin/bench_render --benchmark_repetitions=7 --benchmark_report_aggregates_only=true
// Each run reports the median time and Mrays/s (rays traced per second of wall time).
#include <benchmark/benchmark.h>

#include "renderer.h"
#include "scene_io.h"

namespace {

whitted::Scene seedScene(whitted::Precision precision) {
    whitted::Scene scene = whitted::loadScene(WHITTED_SCENES_DIR "/seed.json");
    scene.render.width = 1280;
    scene.render.height = 720;
    scene.render.precision = precision;
    return scene;
}

void renderSeed(benchmark::State& state, whitted::Precision precision) {
    const whitted::Scene scene = seedScene(precision);
    whitted::RenderOptions options;
    options.progressive = false;
    options.threads = static_cast<int>(state.range(0));
    std::uint64_t rays = 0;
    for (auto _ : state) {
        const whitted::RenderResult result = whitted::render(scene, options);
        rays += result.rays.total();
        benchmark::DoNotOptimize(result.image.rgb.data());
    }
    state.counters["Mrays/s"] = benchmark::Counter(double(rays) / 1e6, benchmark::Counter::kIsRate);
}

void BM_SeedFloat(benchmark::State& state) {
    renderSeed(state, whitted::Precision::Float);
}
void BM_SeedDouble(benchmark::State& state) {
    renderSeed(state, whitted::Precision::Double);
}

// Arg: threads; 0 means all cores.
BENCHMARK(BM_SeedFloat)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SeedDouble)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
