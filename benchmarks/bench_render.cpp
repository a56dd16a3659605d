// Render speed of the seed scene at 1280x720, one sample per pixel, one-shot:
// our tracer against a plain scalar tracer (plain_tracer.h) in the same run, in
// float and double, on one thread and on all cores. Run:
//   build/bin/bench_render --benchmark_repetitions=7 --benchmark_report_aggregates_only=true
// Time is wall time per image; Mrays/s counts every ray traced (camera, shadow,
// reflection, refraction) per second of wall time. Compare rows of one run: the
// machines are shared, so absolute times drift between runs.
//
// BM_SeedFloat and BM_SeedDouble run the kernel the dispatcher picks (or the one
// WHITTED_KERNEL names); BM_Kernel/<name>/<precision> runs each kernel this CPU
// supports, on one thread, so that the kernels compare within one run.
#include <benchmark/benchmark.h>

#include <string>

#include "plain_tracer.h"
#include "scene/scene_io.h"
#include "tracer/kernel_dispatch.h"
#include "tracer/renderer.h"

namespace {

using whitted::Precision;

whitted::Scene seedScene(Precision precision) {
    whitted::Scene scene = whitted::loadScene(WHITTED_SCENES_DIR "/seed.json");
    scene.render.width = 1280;
    scene.render.height = 720;
    scene.render.precision = precision;
    return scene;
}

void setRate(benchmark::State& state, double rays) {
    state.counters["Mrays/s"] = benchmark::Counter(rays / 1e6, benchmark::Counter::kIsRate);
}

void ours(benchmark::State& state, Precision precision) {
    const whitted::Scene scene = seedScene(precision);
    whitted::RenderOptions options = whitted::oneShotOptions();
    options.threads = static_cast<int>(state.range(0));
    double rays = 0;
    for (auto _ : state) {
        const whitted::RenderResult result = whitted::render(scene, options);
        rays += double(result.rays.total());
        benchmark::DoNotOptimize(result.image.rgb.data());
    }
    setRate(state, rays);
}

template <typename T>
void plain(benchmark::State& state) {
    const whitted::Scene scene = seedScene(Precision::Float);
    const int threads = whitted::resolveThreadCount(static_cast<int>(state.range(0)));
    double rays = 0;
    for (auto _ : state) {
        whitted::Image image;
        rays += double(whitted::bench::renderPlain<T>(scene, threads, image));
        benchmark::DoNotOptimize(image.rgb.data());
    }
    setRate(state, rays);
}

void BM_SeedFloat(benchmark::State& state) {
    ours(state, Precision::Float);
}
void BM_SeedDouble(benchmark::State& state) {
    ours(state, Precision::Double);
}
void BM_PlainScalarFloat(benchmark::State& state) {
    plain<float>(state);
}
void BM_PlainScalarDouble(benchmark::State& state) {
    plain<double>(state);
}

// Arg: threads; 0 means all cores.
#define WHITTED_BENCH(fn) \
    BENCHMARK(fn)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime()
WHITTED_BENCH(BM_SeedFloat);
WHITTED_BENCH(BM_PlainScalarFloat);
WHITTED_BENCH(BM_SeedDouble);
WHITTED_BENCH(BM_PlainScalarDouble);

// The seed on one thread in the named kernel; the automatic choice afterwards.
void oneKernel(benchmark::State& state, const std::string& kernel, Precision precision) {
    whitted::useKernel(kernel);
    ours(state, precision);
    whitted::useKernel("");
}

void registerKernelBenchmarks() {
    for (const std::string& kernel : whitted::supportedKernelNames()) {
        for (const Precision precision : {Precision::Float, Precision::Double}) {
            const std::string name =
                "BM_Kernel/" + kernel + "/" + std::string(whitted::precisionName(precision));
            benchmark::RegisterBenchmark(name.c_str(), oneKernel, kernel, precision)
                ->Arg(1)
                ->Unit(benchmark::kMillisecond)
                ->UseRealTime();
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    registerKernelBenchmarks();
    benchmark::AddCustomContext("kernel", whitted::activeKernelDescription());
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
