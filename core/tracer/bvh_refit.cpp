// The sphere BVH kept between renders (bvh.h, BvhCache): refit when the
// spheres moved, rebuilt when their number changed or refits wore the tree
// out (its SAH cost grew past kWornOut times the built one's).
#include <atomic>
#include <numeric>
#include <vector>

#include "base/parallel_for.h"
#include "tracer/bvh.h"
#include "tracer/bvh_boxes.h"

namespace whitted {

using namespace bvh_build;

template <typename T>
bool refitSphereBvh(SphereBvh<T>& bvh, std::span<const glm::dvec3> centres,
                    std::span<const double> radii, int threads) {
    if (bvh.lazy) return false;  // its unbuilt subtrees have no nodes to refit
    threads = resolveThreadCount(threads);
    std::atomic<bool> inTree{true};
    forChunks(static_cast<int>(bvh.leafSpheres.size()), threads, [&](int j) {
        const std::int32_t k = bvh.leafSpheres[j].index;
        if (!inReach<T>(centres[k], radii[k])) inTree = false;
    });
    if (!inTree) return false;
    // The leaves first, on every thread: they hold every sphere, and so most of
    // the work. Their boxes are grown in double and rounded outward once per
    // node: rounding is monotonic, so that is the box the build's per-sphere
    // rounding gives, for a sixth of the roundings.
    forChunks(static_cast<int>(bvh.nodes.size()), threads, [&](int i) {
        BvhNode& leaf = bvh.nodes[i];
        if (leaf.count <= 0) return;
        LaneBox<double> box;
        for (int j = leaf.first; j < leaf.first + leaf.count; ++j) {
            const std::int32_t k = bvh.leafSpheres[j].index;
            box.grow(sphereBox(centres[k], radii[k]));
        }
        storeBox(leaf, box);
    });
    // Then the inner nodes: children always come after their parent (the
    // build), so one pass from the end meets every child before its parent.
    for (std::size_t i = bvh.nodes.size(); i-- > 0;) {
        BvhNode& node = bvh.nodes[i];
        if (node.count >= 0) continue;  // a leaf, or the padding
        LaneBox<double> box;
        box.grow(boxOf<double>(bvh.nodes[node.first]));
        box.grow(boxOf<double>(bvh.nodes[node.first + 1]));
        storeBox(node, box);
    }
    return true;
}

template <typename T>
double sahCost(const SphereBvh<T>& bvh, int threads) {
    // Summed by chunk, in parallel, then the chunks in order: the same sum
    // for any number of threads.
    const int nodes = static_cast<int>(bvh.nodes.size());
    std::vector<double> chunkCost(chunkCount(nodes));
    forEachChunk(nodes, resolveThreadCount(threads), [&](int c, int begin, int end) {
        double cost = 0;
        for (int i = begin; i < end; ++i) {
            const BvhNode& n = bvh.nodes[i];
            cost += double(boxOf<T>(n).halfArea()) * (n.count > 0 ? n.count : 1);
        }
        chunkCost[c] = cost;
    });
    return std::accumulate(chunkCost.begin(), chunkCost.end(), 0.0);
}

namespace {

// The leaves' copies of their spheres' values, from `spheres`, on `threads`
// threads: at a million spheres the reads are scattered over 40 MB.
template <typename T>
void fillLeafSpheres(SphereBvh<T>& bvh, const SphereSet<T>& spheres, int threads) {
    forChunks(static_cast<int>(bvh.leafSpheres.size()), threads,
              [&](int i) { bvh.leafSpheres[i] = spheres.leafSphere(bvh.leafSpheres[i].index); });
}

}  // namespace

template <typename T>
std::shared_ptr<const SphereBvh<T>> sphereBvhFor(std::span<const glm::dvec3> centres,
                                                 std::span<const double> radii,
                                                 const SphereSet<T>& spheres, BvhCache* cache,
                                                 const glm::dvec3& frameOrigin, int threads) {
    threads = resolveThreadCount(threads);
    BvhBuildOptions build;
    build.threads = threads;
    if (!cache) {
        build.lazy = true;
        auto tree = std::make_shared<SphereBvh<T>>(buildSphereBvh<T>(centres, radii, build));
        if (!tree->lazy) fillLeafSpheres(*tree, spheres, threads);  // else each job fills its own
        return tree;
    }
    BvhCache::Entry<T>& kept = cache->entry<T>();
    // use_count 1: no earlier render still reads the tree being refit or refilled.
    const bool keptAlone = kept.tree && kept.tree.use_count() == 1 && kept.spheres == radii.size();
    if (keptAlone && cache->geometryRevision != 0 &&
        kept.geometryRevision == cache->geometryRevision && kept.frameOrigin == frameOrigin) {
        fillLeafSpheres(*kept.tree, spheres, threads);  // the eye may have moved in the frame
        ++cache->reuses;
        return kept.tree;
    }
    kept.geometryRevision = cache->geometryRevision;
    kept.frameOrigin = frameOrigin;
    if (keptAlone && refitSphereBvh(*kept.tree, centres, radii, threads) &&
        sahCost(*kept.tree, threads) <= BvhCache::kWornOut * kept.builtCost) {
        fillLeafSpheres(*kept.tree, spheres, threads);
        ++cache->refits;
        return kept.tree;
    }
    kept.tree = std::make_shared<SphereBvh<T>>(buildSphereBvh<T>(centres, radii, build));
    fillLeafSpheres(*kept.tree, spheres, threads);
    kept.spheres = radii.size();
    kept.builtCost = sahCost(*kept.tree, threads);
    ++cache->builds;
    return kept.tree;
}

#define WHITTED_BVH_REFIT(T)                                                                  \
    template bool refitSphereBvh<T>(SphereBvh<T>&, std::span<const glm::dvec3>,               \
                                    std::span<const double>, int);                            \
    template double sahCost<T>(const SphereBvh<T>&, int);                                     \
    template std::shared_ptr<const SphereBvh<T>> sphereBvhFor<T>(                             \
        std::span<const glm::dvec3>, std::span<const double>, const SphereSet<T>&, BvhCache*, \
        const glm::dvec3&, int);
WHITTED_BVH_REFIT(float)
WHITTED_BVH_REFIT(double)
#undef WHITTED_BVH_REFIT

}  // namespace whitted
