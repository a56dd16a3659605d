#include "analysis/speed_probe.h"

#include <algorithm>
#include <cmath>

#include "analysis/tradeoff.h"
#include "base/thread_cpu_time.h"
#include "tracer/renderer.h"

namespace whitted {

namespace {

// A jittered probe's samples a pixel. A render of more than one sample a
// pixel traces no centres (pixelSample()): each of its samples is jittered.
constexpr int kJitteredSamples = 8;
// Past this, a few pixels' timing says nothing about the power of size.
constexpr double kLargestSizePower = 1.0;

struct Timed {
    double rays = 0.0, cpuSeconds = 0.0;
};

// The cheaper of two renders, in the CPU time of the threads that traced
// it: a render the machine's other work slowed costs no more CPU time, but
// the caches it shares still vary.
Timed timedRender(const Scene& scene, const StopPredicate& stop) {
    Timed best;
    for (int attempt = 0; attempt < 2; ++attempt) {
        const RenderResult r = render(scene, oneShotOptions(), {}, stop);
        if (attempt == 0 || r.tilesCpuSeconds < best.cpuSeconds)
            best = {double(r.rays.total()), r.tilesCpuSeconds};
    }
    return best;
}

// The cost a ray of a one-sample render (pixel centres, in coherent rows)
// and of a render of several jittered samples a pixel.
RayCost rayCostAt(const Scene& scene, int side, const StopPredicate& stop) {
    const int longest = std::max(scene.render.width, scene.render.height);
    TradeoffSettings s{1, scene.render.maxDepth, scene.render.precision,
                       std::min(1.0, double(side) / longest)};
    Scene probe = withSettings(scene, s);
    const Timed centres = timedRender(probe, stop);
    probe.render.samplesPerPixel = kJitteredSamples;
    const Timed jittered = timedRender(probe, stop);
    RayCost cost;
    cost.centre = centres.cpuSeconds / std::max(1.0, centres.rays);
    cost.jittered = jittered.cpuSeconds / std::max(1.0, jittered.rays);
    return cost;
}

// The render of one pixel, in the CPU time of this thread, which prepares
// the scene: the overhead, as any other render would pay it.
double overheadOf(const Scene& scene, const StopPredicate& stop) {
    RenderOptions options = oneShotOptions();
    options.region = PixelRect{0, 0, 1, 1};
    const double start = threadCpuSeconds();
    render(scene, options, {}, stop);
    return threadCpuSeconds() - start;
}

// The threads a render of the whole picture runs on: no more than its tiles.
int threadsFor(const Scene& scene) {
    const RenderOptions options;
    const int tileSide = std::max(1, options.tileSize);
    const int tiles = ((scene.render.width + tileSide - 1) / tileSide) *
                      ((scene.render.height + tileSide - 1) / tileSide);
    return std::max(1, std::min(resolveThreadCount(options.threads), tiles));
}

}  // namespace

SpeedProbe probeSpeed(const Scene& scene, int side, const StopPredicate& stop) {
    SpeedProbe probe;
    probe.overheadSeconds = std::min(overheadOf(scene, stop), overheadOf(scene, stop));
    probe.side = std::min(side, std::max(scene.render.width, scene.render.height));
    probe.atSide = rayCostAt(scene, probe.side, stop);
    probe.atHalfSide = rayCostAt(scene, probe.side / 2, stop);
    const double all = probe.atSide.centre + probe.atSide.jittered;
    const double allAtHalf = probe.atHalfSide.centre + probe.atHalfSide.jittered;
    if (all > 0.0 && allAtHalf > 0.0)
        probe.sizePower = std::clamp(std::log2(allAtHalf / all), 0.0, kLargestSizePower);
    return probe;
}

double predictSeconds(const SpeedProbe& probe, const Scene& scene, double rays) {
    const int longest = std::max(scene.render.width, scene.render.height);
    const double doublings = std::log2(double(longest) / std::max(1, probe.side));
    // Past the probe's side each doubling gains about half what the one before
    // did, p (1 - 2^-d) over d doublings: the full power, from 80 to 160
    // pixels, predicted renders at 640 pixels 0.62 to 1.19 of their time
    // (0.81 in the middle), halving it 0.73 to 1.59 (1.07); docs/quality.md.
    const double exponent = doublings > 0.0 ? probe.sizePower * (1.0 - std::pow(0.5, doublings))
                                            : probe.sizePower * doublings;
    const double finer = std::pow(2.0, -exponent);
    const RayCost& cost = probe.atSide;
    const double costARay = scene.render.samplesPerPixel > 1 ? cost.jittered : cost.centre;
    const double cpuSeconds = finer * rays * costARay;
    return probe.overheadSeconds + cpuSeconds / threadsFor(scene);
}

}  // namespace whitted
