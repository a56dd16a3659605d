#include "analysis/precision_compare.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

#include "analysis/ray_decisions.h"
#include "image/heat_map.h"
#include "image/image_compare.h"
#include "tracer/tracer.h"

namespace whitted {

namespace {

struct DecisionCounts {
    std::size_t hit = 0, shadow = 0, tir = 0;
};

// Calls fn with the scene prepared in its own precision.
template <typename Fn>
void withPrepared(const Scene& scene, Fn&& fn) {
    if (scene.render.precision == Precision::Float)
        fn(prepareScene<float>(scene));
    else
        fn(prepareScene<double>(scene));
}

// The pixels of each kind of first differing decision, rows shared out among all
// cores. False when stopped.
template <typename A, typename B>
bool countDecisions(const PreparedScene<A>& a, const PreparedScene<B>& b, const StopPredicate& stop,
                    DecisionCounts& total) {
    const int width = a.width, height = a.height;
    std::atomic<int> nextRow{0};
    std::atomic<bool> stopped{false};
    std::vector<DecisionCounts> counts(resolveThreadCount(0));
    auto work = [&](DecisionCounts& c) {
        std::vector<Decision> da, db;
        for (int y = nextRow++; y < height; y = nextRow++) {
            if (stopped.load(std::memory_order_relaxed) || (stop && stop())) {
                stopped = true;
                return;
            }
            for (int x = 0; x < width; ++x) {
                pixelDecisions(a, x, y, da);
                pixelDecisions(b, x, y, db);
                switch (firstDifference(da, db)) {
                    case DecisionDifference::None:
                        break;
                    case DecisionDifference::Hit:
                        ++c.hit;
                        break;
                    case DecisionDifference::Shadow:
                        ++c.shadow;
                        break;
                    case DecisionDifference::Tir:
                        ++c.tir;
                        break;
                }
            }
        }
    };
    std::vector<std::thread> pool;
    for (std::size_t t = 1; t < counts.size(); ++t) pool.emplace_back(work, std::ref(counts[t]));
    work(counts[0]);  // the calling thread is one of the workers, as in render()
    for (std::thread& t : pool) t.join();
    for (const DecisionCounts& c : counts) {
        total.hit += c.hit;
        total.shadow += c.shadow;
        total.tir += c.tir;
    }
    return !stopped;
}

Scene resized(Scene scene, int width, int height) {
    scene.render.width = width;
    scene.render.height = height;
    return scene;
}

Scene withPrecision(Scene scene, Precision precision) {
    scene.render.precision = precision;
    return scene;
}

}  // namespace

PrecisionComparison compareScenes(const Scene& a, const Scene& b, int width, int height,
                                  const StopPredicate& stop) {
    PrecisionComparison out;
    out.width = width;
    out.height = height;
    out.pixels = std::size_t(width) * std::size_t(height);
    const Scene sa = resized(a, width, height), sb = resized(b, width, height);

    const RenderOptions options = oneShotOptions();
    const RenderResult ra = render(sa, options, {}, stop);
    const RenderResult rb = ra.completed ? render(sb, options, {}, stop) : RenderResult{};
    if (!rb.completed) {
        out.stopped = true;
        return out;
    }

    for (std::size_t p = 0; p < out.pixels; ++p) {
        const float d = displayDifference(&ra.image.rgb[3 * p], &rb.image.rgb[3 * p]);
        out.largest = std::max(out.largest, d);
        out.over1 += d > 1.0f / 255.0f;
        out.over2 += d > 2.0f / 255.0f;
    }
    out.heatMap = heatMap(ra.image, rb.image);

    DecisionCounts counts;
    withPrepared(sa, [&](const auto& pa) {
        withPrepared(sb,
                     [&](const auto& pb) { out.stopped = !countDecisions(pa, pb, stop, counts); });
    });
    out.hitDiffers = counts.hit;
    out.shadowDiffers = counts.shadow;
    out.tirDiffers = counts.tir;
    return out;
}

PrecisionComparison comparePrecisions(const Scene& scene, int width, int height,
                                      const StopPredicate& stop) {
    return compareScenes(withPrecision(scene, Precision::Float),
                         withPrecision(scene, Precision::Double), width, height, stop);
}

}  // namespace whitted
