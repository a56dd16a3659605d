#include "analysis/speed_probe.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "base/thread_cpu_time.h"
#include "tracer/bvh.h"

namespace whitted {

namespace {

// A jittered probe's samples a pixel. A render of more than one sample a
// pixel traces no centres (pixelSample()): each of its samples is jittered.
constexpr int kJitteredSamples = 8;

struct Timed {
    double rays = 0.0, cpuSeconds = 0.0;
};

// The tiles at `samples` a pixel, in one render on the threads the
// picture's render would use (a core runs slower beside a busy one), the
// cheaper of two in the CPU time of the threads that traced it: a render
// the machine's other work slowed costs no more CPU time, but the caches it
// shares still vary. The renders share one tree, built once: a tree built
// lazily as rays reach its nodes (bvh.h) is a render's cost once, not four times.
Timed timedTiles(Scene scene, int samples, const std::vector<PixelRect>& tiles, BvhCache& trees,
                 const StopPredicate& stop) {
    scene.render.samplesPerPixel = samples;
    RenderOptions options = oneShotOptions();
    options.sceneValidated = true;  // renderOverheadSeconds() rendered it
    options.regions = tiles;
    options.bvhCache = &trees;
    Timed best;
    for (int attempt = 0; attempt < 2; ++attempt) {
        const RenderResult r = render(scene, options, {}, stop);
        if (attempt == 0 || r.tilesCpuSeconds < best.cpuSeconds)
            best = {double(r.rays.total()), r.tilesCpuSeconds};
    }
    return best;
}

double perRay(const Timed& t) {
    return t.cpuSeconds / std::max(1.0, t.rays);
}

}  // namespace

double renderOverheadSeconds(const Scene& scene, const StopPredicate& stop) {
    RenderOptions options = oneShotOptions();
    options.regions = {PixelRect{0, 0, 1, 1}};
    const double start = threadCpuSeconds();
    render(scene, options, {}, stop);
    return threadCpuSeconds() - start;
}

std::vector<PixelRect> probeTiles(int width, int height, int pixels) {
    if (double(width) * height <= pixels) return {PixelRect{0, 0, width, height}};
    const int side = kSpeedProbeTileSide;
    const int columns = (width + side - 1) / side, rows = (height + side - 1) / side;
    const int wanted = std::max(1, (pixels + side * side - 1) / (side * side));
    const double goldenFraction = (std::sqrt(5.0) - 1.0) / 2.0;
    std::set<std::pair<int, int>> chosen;  // (row, column), each once
    for (int i = 0; i < wanted; ++i) {
        const int column = std::min(columns - 1, int((i + 0.5) * columns / wanted));
        const double along = std::fmod(0.5 + i * goldenFraction, 1.0);
        chosen.insert({std::min(rows - 1, int(along * rows)), column});
    }
    std::vector<PixelRect> tiles;
    for (const auto& [row, column] : chosen) {
        const int x = column * side, y = row * side;
        tiles.push_back({x, y, std::min(side, width - x), std::min(side, height - y)});
    }
    return tiles;
}

SpeedProbe probeSpeed(const Scene& scene, int pixels, const StopPredicate& stop) {
    SpeedProbe probe;
    probe.overheadSeconds =
        std::min(renderOverheadSeconds(scene, stop), renderOverheadSeconds(scene, stop));
    const std::vector<PixelRect> tiles =
        probeTiles(scene.render.width, scene.render.height, pixels);
    for (const PixelRect& t : tiles) probe.pixels += t.width * t.height;
    BvhCache trees;
    probe.cost.centre = perRay(timedTiles(scene, 1, tiles, trees, stop));
    probe.cost.jittered = perRay(timedTiles(scene, kJitteredSamples, tiles, trees, stop));
    return probe;
}

double predictSeconds(const SpeedProbe& probe, const Scene& scene, double rays) {
    const double costARay =
        scene.render.samplesPerPixel > 1 ? probe.cost.jittered : probe.cost.centre;
    return probe.overheadSeconds + rays * costARay / renderThreads(scene.render);
}

}  // namespace whitted
