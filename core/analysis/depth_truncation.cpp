#include "analysis/depth_truncation.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>

#include "scene/scene_io.h"
#include "tracer/scalar_ray_tree.h"

namespace whitted {

namespace {

// Sums the cut-off weights of a pixel's tree. Paths lighter than `pruneBelow`
// are not followed; their subtree's cut-off is counted at its largest possible
// value instead, so the map never understates what raising the depth could do.
struct CutOffSum {
    static constexpr bool kWantsShadows = false;
    double pruneBelow = 0.0;
    double factor = 1.0;  // the scene's largest kr + kt: how much a bounce can pass on
    int maxDepth = 0;
    double sum = 0.0;
    void hit(int) {}
    void shadow(int) {}
    void tir(bool) {}
    void cutOff(double weight) { sum += weight; }
    bool descend(double weight, int depth) {
        if (weight >= pruneBelow) return true;
        sum += weight * std::pow(factor, maxDepth - depth + 1);
        return false;
    }
};

// The map with paths lighter than pruneBelow bounded rather than followed: the
// tree of a glass scene doubles with each level, so a search up to depth 64
// cannot follow every path.
Image truncationMap(const Scene& scene, double pruneBelow, const StopPredicate& stop) {
    const PreparedScene<double> s = prepareScene<double>(scene);
    double factor = 0.0;
    for (const PreparedMaterial<double>& m : s.materials)
        factor = std::max(factor, m.reflectivity + m.transparency);
    Image map(s.width, s.height);
    // Rows shared out to every core; each row is independent.
    std::atomic<int> nextRow{0};
    auto worker = [&] {
        for (int j; (j = nextRow++) < s.height;) {
            if (stop && stop()) return;
            for (int i = 0; i < s.width; ++i) {
                CutOffSum sum{pruneBelow, factor, s.maxDepth};
                ScalarRayTree<double, CutOffSum>(s, sum).tracePixel(i, j);
                float* out = map.pixel(i, j);
                out[0] = out[1] = out[2] = float(sum.sum);
            }
        }
    };
    std::vector<std::thread> helpers;
    for (int t = 1; t < resolveThreadCount(0); ++t) helpers.emplace_back(worker);
    worker();
    for (std::thread& h : helpers) h.join();
    return map;
}

}  // namespace

Image depthTruncationMap(const Scene& scene, const StopPredicate& stop) {
    return truncationMap(scene, 0.0, stop);
}

float largestTruncation(const Image& map) {
    float largest = 0.0f;
    for (float v : map.rgb) largest = std::max(largest, v);
    return largest;
}

int depthWithinTolerance(const Scene& scene, double tolerance, const StopPredicate& stop) {
    Scene s = scene;
    // Every step of the tree multiplies the weight by kr + kt <= 2, so the map
    // can shrink only as fast as the scene's materials allow; walk up until it is
    // below the tolerance. Each map costs a scalar walk per pixel, so this runs
    // at a reduced size (the deepest chains are a property of the geometry, and
    // 160 pixels across catch the ones that matter for the picture) and bounds
    // paths lighter than tolerance / 64 instead of following them.
    const int longest = std::max(s.render.width, s.render.height);
    if (longest > 160) {
        s.render.width = std::max(1, s.render.width * 160 / longest);
        s.render.height = std::max(1, s.render.height * 160 / longest);
    }
    for (int depth = 0; depth < kMaxDepth && !(stop && stop()); ++depth) {
        s.render.maxDepth = depth;
        const Image map = truncationMap(s, tolerance / 64.0, stop);
        if (stop && stop()) break;  // the map is incomplete
        if (largestTruncation(map) < tolerance) return depth;
    }
    return kMaxDepth;
}

}  // namespace whitted
