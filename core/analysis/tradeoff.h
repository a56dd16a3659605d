// The speed/accuracy trade: renders of one scene over a grid of
// samples per pixel, max_depth, precision and resolution scale, each timed and
// compared with a reference render. Qt-free, shared by whitted-tradeoff and the
// editor's Measure action.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <vector>

#include "image/image.h"
#include "image/image_error.h"
#include "scene/scene.h"
#include "tracer/renderer.h"

namespace whitted {

// What a user can trade: everything else comes from the scene.
struct TradeoffSettings {
    int samplesPerPixel = 1;
    int maxDepth = 5;
    Precision precision = Precision::Float;
    double resolutionScale = 1.0;  // width and height times this, rounded, at least 1
    bool operator==(const TradeoffSettings&) const = default;
};

// The scene with `settings` applied (render size scaled, samples, depth, precision).
Scene withSettings(const Scene& scene, const TradeoffSettings& settings);

struct TradeoffGrid {
    std::vector<int> samples{1, 2, 4, 8, 16, 32, 64, 128, 256};
    std::vector<int> depths{0, 1, 2, 3, 4, 5, 6, 7, 8};
    std::vector<Precision> precisions{Precision::Float, Precision::Double};
    std::vector<double> scales{0.25, 0.5, 1.0};
    // Each point is rendered at least minRuns times and until it has taken
    // minSeconds in all, at most maxRuns times; its time is the median.
    int minRuns = 3;
    int maxRuns = 9;
    double minSeconds = 0.2;
};

// Two past `depthWithinTolerance`, at most kMaxDepth: the depth past which a
// reference would change nothing a picture shows.
inline int settledReferenceDepth(int depthWithinTolerance) {
    return std::min(kMaxDepth, depthWithinTolerance + 2);
}

// The reference: the scene in double with `samples` samples per pixel and a
// max_depth of settledReferenceDepth(depthWithinTolerance(scene)), capped at
// kDeepestChosen or the scene's own max_depth, whichever is deeper: where
// rays bounce in glass without losing weight the search returns kMaxDepth,
// and a reference at depth 64 would never end.
struct ReferenceRender {
    Scene scene;  // the settings it was rendered with
    Image image;
    double seconds = 0.0;
};
ReferenceRender renderReference(const Scene& scene, int samples = 1024,
                                const StopPredicate& stop = {});

struct TradeoffPoint {
    TradeoffSettings settings;
    int width = 0, height = 0;  // the render size at this point's scale
    double seconds = 0.0;       // median wall time of render(), one-shot
    int runs = 0;
    std::uint64_t rays = 0;       // rays of one render
    double mraysPerSecond = 0.0;  // rays / seconds / 1e6
    ErrorStats error;             // against the reference
    bool pareto = false;          // on the front: no point is both faster and more accurate
};

struct TradeoffProgress {
    int done = 0;                         // points finished
    int total = 0;                        // points in the grid
    const TradeoffPoint* last = nullptr;  // the point just finished
};
using TradeoffCallback = std::function<void(const TradeoffProgress&)>;

// Every grid point, in grid order (scale, precision, depth, samples), timed
// and compared with `reference` (which must be at the scene's render size).
// Marks the Pareto front by seconds and rmseSrgb8. Returns the points finished
// so far when `stop` says so.
std::vector<TradeoffPoint> runTradeoff(const Scene& scene, const Image& reference,
                                       const TradeoffGrid& grid,
                                       const TradeoffCallback& progress = {},
                                       const StopPredicate& stop = {});

// Sets `pareto` on the points that are more accurate (rmseSrgb8, by at least
// 0.1 %) than every faster point.
void markParetoFront(std::vector<TradeoffPoint>& points);

// The progressive renderer refining the scene (its own settings): the error
// against `reference` and the elapsed time at the end of every pass.
struct ProgressiveSample {
    int pass = 0;
    int samples = 0;       // samples per pixel after the pass (0: the preview)
    double seconds = 0.0;  // since render() started, to the pass's last tile
    ErrorStats error;
};
std::vector<ProgressiveSample> progressiveCurve(const Scene& scene, const Image& reference,
                                                const StopPredicate& stop = {});

}  // namespace whitted
