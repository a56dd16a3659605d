#include "analysis/tradeoff.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <mutex>

#include "analysis/depth_truncation.h"
#include "base/elapsed.h"

namespace whitted {

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

Scene withSettings(const Scene& scene, const TradeoffSettings& settings) {
    Scene s = scene;
    auto scaled = [&](int size) {
        return std::clamp(int(std::lround(size * settings.resolutionScale)), 1, kMaxImageSize);
    };
    s.render.width = scaled(scene.render.width);
    s.render.height = scaled(scene.render.height);
    s.render.samplesPerPixel = settings.samplesPerPixel;
    s.render.maxDepth = settings.maxDepth;
    s.render.precision = settings.precision;
    return s;
}

ReferenceRender renderReference(const Scene& scene, int samples, const StopPredicate& stop) {
    ReferenceRender ref;
    ref.scene = scene;
    ref.scene.render.precision = Precision::Double;
    ref.scene.render.samplesPerPixel = samples;
    const int settled = settledReferenceDepth(depthWithinTolerance(scene, 1.0 / 1024.0, stop));
    ref.scene.render.maxDepth = std::min(settled, std::max(kDeepestChosen, scene.render.maxDepth));
    RenderResult result = render(ref.scene, oneShotOptions(), {}, stop);
    ref.image = std::move(result.image);
    ref.seconds = result.seconds;
    return ref;
}

std::vector<TradeoffPoint> runTradeoff(const Scene& scene, const Image& reference,
                                       const TradeoffGrid& grid, const TradeoffCallback& progress,
                                       const StopPredicate& stop) {
    std::vector<TradeoffPoint> points;
    TradeoffProgress state;
    state.total =
        int(grid.scales.size() * grid.precisions.size() * grid.depths.size() * grid.samples.size());
    auto stopped = [&] { return stop && stop(); };
    for (double scale : grid.scales)
        for (Precision precision : grid.precisions)
            for (int depth : grid.depths)
                for (int samples : grid.samples) {
                    TradeoffPoint point;
                    point.settings = {samples, depth, precision, scale};
                    const Scene s = withSettings(scene, point.settings);
                    point.width = s.render.width;
                    point.height = s.render.height;
                    std::vector<double> times;
                    double total = 0.0;
                    RenderResult last;
                    while (int(times.size()) < grid.maxRuns &&
                           (int(times.size()) < grid.minRuns || total < grid.minSeconds)) {
                        last = render(s, oneShotOptions(), {}, stop);
                        if (!last.completed || stopped()) {
                            markParetoFront(points);
                            return points;
                        }
                        times.push_back(last.seconds);
                        total += last.seconds;
                    }
                    point.runs = int(times.size());
                    point.seconds = median(times);
                    point.rays = last.rays.total();
                    point.mraysPerSecond =
                        point.seconds > 0.0 ? double(point.rays) / point.seconds / 1e6 : 0.0;
                    point.error = measureError(last.image, reference);
                    points.push_back(point);
                    ++state.done;
                    state.last = &points.back();
                    if (progress) progress(state);
                }
    markParetoFront(points);
    return points;
}

void markParetoFront(std::vector<TradeoffPoint>& points) {
    std::vector<TradeoffPoint*> order;
    for (TradeoffPoint& p : points) order.push_back(&p);
    std::sort(order.begin(), order.end(), [](const TradeoffPoint* a, const TradeoffPoint* b) {
        if (a->seconds != b->seconds) return a->seconds < b->seconds;
        return a->error.rmseSrgb8 < b->error.rmseSrgb8;
    });
    // Fastest first: a point is on the front when it is more accurate than
    // every faster point, by at least 0.1 %: settings that change nothing
    // (depth past the longest chain) differ only by rounding and timing noise.
    double best = INFINITY;
    for (TradeoffPoint* p : order) {
        p->pareto = p->error.rmseSrgb8 < best * (1.0 - 1e-3);
        best = std::min(best, p->error.rmseSrgb8);
    }
}

std::vector<ProgressiveSample> progressiveCurve(const Scene& scene, const Image& reference,
                                                const StopPredicate& stop) {
    // The callback keeps its own copy of the image, tile by tile (each tile is
    // stable while its callback runs), and snapshots it when a pass's last tile
    // arrives: the picture a viewer has at that moment. The errors are computed
    // after the render, so measuring does not slow the passes it measures.
    struct Snapshot {
        int pass, samples;
        double seconds;
        Image image;
    };
    std::mutex mutex;
    Image shown(scene.render.width, scene.render.height);
    std::map<int, int> tilesSeen;
    std::vector<Snapshot> snapshots;
    const auto start = std::chrono::steady_clock::now();
    auto onTile = [&](const TileUpdate& u) {
        std::lock_guard<std::mutex> lock(mutex);
        copyTile(u, shown);
        if (++tilesSeen[u.progress.pass] == u.progress.tilesInPass) {
            const double seconds = secondsSince(start);
            snapshots.push_back({u.progress.pass, u.progress.samples, seconds, shown});
        }
    };
    render(scene, RenderOptions{}, onTile, stop);
    std::vector<ProgressiveSample> curve;
    for (const Snapshot& s : snapshots)
        curve.push_back({s.pass, s.samples, s.seconds, measureError(s.image, reference)});
    return curve;
}

}  // namespace whitted
