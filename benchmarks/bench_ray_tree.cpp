// One pixel's ray tree (analysis/pixel_ray_tree.h, `whitted-render --inspect`)
// on each shipped scene at its own size, the centre pixel, in its own
// precision: the whole call, the scene's preparation (its sphere tree) included.
// Google Benchmark; prints its figures.
#include <benchmark/benchmark.h>

#include <string>

#include "analysis/pixel_ray_tree.h"
#include "scene/scene_io.h"

namespace {

void BM_PixelRayTree(benchmark::State& state, const std::string& file) {
    const whitted::Scene scene = whitted::loadScene(WHITTED_SCENES_DIR "/" + file);
    const int x = scene.render.width / 2, y = scene.render.height / 2;
    int rays = 0;
    for (auto _ : state) {
        const whitted::PixelRayTree tree = whitted::pixelRayTree(scene, x, y);
        benchmark::DoNotOptimize(tree.value);
        rays = int(tree.root.children.size());
    }
    state.counters["root_children"] = rays;
    state.counters["spheres"] = double(scene.spheres.size());
}

}  // namespace

BENCHMARK_CAPTURE(BM_PixelRayTree, seed, std::string("seed.json"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_PixelRayTree, glass, std::string("glass.json"))
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_PixelRayTree, mirrors, std::string("mirrors.json"))
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_PixelRayTree, coloured_shadows, std::string("coloured-shadows.json"))
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_PixelRayTree, whitted_1980, std::string("whitted-1980.json"))
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_PixelRayTree, field, std::string("field.json"))
    ->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
