// The sphere BVH kept between renders (bvh.h, BvhCache): refit when the
// spheres moved, rebuilt when their number changed or refits wore the tree
// out (its SAH cost grew past kWornOut times the built one's).
#include <atomic>
#include <cstdint>
#include <numeric>
#include <optional>
#include <vector>

#include "base/parallel_for.h"
#include "tracer/bvh.h"
#include "tracer/bvh_boxes.h"

namespace whitted {

using namespace bvh_build;

namespace {

// A leaf's box from its spheres' boxes, grown in double and rounded outward
// once: rounding is monotonic, so that is the box the build's per-sphere
// rounding gives, for a sixth of the roundings.
template <typename T>
void refitLeaf(SphereBvh<T>& bvh, int i, std::span<const glm::dvec3> centres,
               std::span<const double> radii) {
    BvhNode& leaf = bvh.nodes[i];
    LaneBox<double> box;
    for (int j = leaf.first; j < leaf.first + leaf.count; ++j) {
        const std::int32_t k = bvh.leafSpheres[j].index;
        box.grow(sphereBox(centres[k], radii[k]));
    }
    storeBox(leaf, box);
}

// An inner node's box from its two children's.
template <typename T>
void refitInner(SphereBvh<T>& bvh, int i) {
    BvhNode& node = bvh.nodes[i];
    LaneBox<double> box;
    box.grow(boxOf<double>(bvh.nodes[node.first]));
    box.grow(boxOf<double>(bvh.nodes[node.first + 1]));
    storeBox(node, box);
}

}  // namespace

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
    // the work.
    forChunks(static_cast<int>(bvh.nodes.size()), threads, [&](int i) {
        if (bvh.nodes[i].count > 0) refitLeaf(bvh, i, centres, radii);
    });
    // Then the inner nodes: children always come after their parent (the
    // build), so one pass from the end meets every child before its parent.
    for (int i = static_cast<int>(bvh.nodes.size()); i-- > 0;)
        if (bvh.nodes[i].count < 0) refitInner(bvh, i);  // not a leaf, nor the padding
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

// Every leaf's copy of its sphere, for the eye at `eye`.
template <typename T>
void fillKeptLeaves(BvhCache::Entry<T>& kept, const SphereSet<T>& spheres, const Vec<T>& eye,
                    int threads) {
    fillLeafSpheres(*kept.tree, spheres, threads);
    kept.filledForEye = eye;
}

// The centres and radii the kept tree is now fit to.
template <typename T>
void rememberFit(BvhCache::Entry<T>& kept, std::span<const glm::dvec3> centres,
                 std::span<const double> radii) {
    kept.fitCentres.assign(centres.begin(), centres.end());
    kept.fitRadii.assign(radii.begin(), radii.end());
}

// Where each sphere lies in the kept tree, and each node's parent; and the
// centres and radii it was fit to.
template <typename T>
void indexKeptTree(BvhCache::Entry<T>& kept, std::span<const glm::dvec3> centres,
                   std::span<const double> radii, int threads) {
    const SphereBvh<T>& bvh = *kept.tree;
    kept.leafOf.assign(radii.size(), -1);
    kept.slotOf.assign(radii.size(), -1);
    kept.parentOf.assign(bvh.nodes.size(), -1);
    // Each node writes its own spheres' entries and its own children's.
    forChunks(static_cast<int>(bvh.nodes.size()), threads, [&](int i) {
        const BvhNode& node = bvh.nodes[i];
        if (node.count < 0) {
            kept.parentOf[node.first] = kept.parentOf[node.first + 1] = i;
            return;
        }
        for (int j = node.first; j < node.first + node.count; ++j) {
            const std::int32_t k = bvh.leafSpheres[j].index;
            kept.leafOf[k] = i;
            kept.slotOf[k] = j;
        }
    });
    rememberFit(kept, centres, radii);
}

// Past this share of the spheres moved, a whole refit, which passes over the
// nodes in parallel where the walks up from each leaf go one at a time. At a
// million spheres, preparing a render after 62,000 moved took 47 ms this way
// and 69 ms with a whole refit; after one moved, 16 ms and 60.
constexpr std::size_t kFewMovedDivisor = 16;

// The spheres whose centre or radius differs from the tree's last fit, in
// index order; none when too many did for a refit of the few.
template <typename T>
std::optional<std::vector<std::int32_t>> movedSpheres(const BvhCache::Entry<T>& kept,
                                                      std::span<const glm::dvec3> centres,
                                                      std::span<const double> radii, int threads) {
    const int count = static_cast<int>(radii.size());
    if (kept.fitRadii.size() != radii.size()) return std::nullopt;
    std::vector<std::vector<std::int32_t>> chunkMoved(chunkCount(count));
    forEachChunk(count, threads, [&](int c, int begin, int end) {
        for (int k = begin; k < end; ++k)
            if (centres[k] != kept.fitCentres[k] || radii[k] != kept.fitRadii[k])
                chunkMoved[c].push_back(k);
    });
    std::vector<std::int32_t> moved;
    for (const std::vector<std::int32_t>& part : chunkMoved)
        moved.insert(moved.end(), part.begin(), part.end());
    if (moved.size() > radii.size() / kFewMovedDivisor) return std::nullopt;
    return moved;
}

// The boxes of the moved spheres' leaves and of every node above them, in
// the whole refit's order (children before parents), so each box is the one
// a whole refit would give. False, with the tree as it was, when a moved
// sphere is beyond what a tree in T can bound.
template <typename T>
bool refitMoved(BvhCache::Entry<T>& kept, std::span<const std::int32_t> moved,
                std::span<const glm::dvec3> centres, std::span<const double> radii) {
    SphereBvh<T>& bvh = *kept.tree;
    for (const std::int32_t k : moved)
        if (kept.leafOf[k] >= 0 && !inReach<T>(centres[k], radii[k])) return false;
    // Each walk up stops where an earlier one passed.
    std::vector<std::uint8_t> dirty(bvh.nodes.size(), 0);
    for (const std::int32_t k : moved)
        for (std::int32_t i = kept.leafOf[k]; i >= 0 && !dirty[i]; i = kept.parentOf[i])
            dirty[i] = 1;
    for (int i = static_cast<int>(bvh.nodes.size()); i-- > 0;) {
        if (!dirty[i]) continue;
        if (bvh.nodes[i].count > 0)
            refitLeaf(bvh, i, centres, radii);
        else
            refitInner(bvh, i);
    }
    for (const std::int32_t k : moved) {
        kept.fitCentres[k] = centres[k];
        kept.fitRadii[k] = radii[k];
    }
    return true;
}

// The leaves' copies: only the moved spheres' when the eye is where the last
// fill saw it (every sphere's camera term depends on it), else all.
template <typename T>
void refillKeptLeaves(BvhCache::Entry<T>& kept, const SphereSet<T>& spheres, const Vec<T>& eye,
                      std::span<const std::int32_t> moved, int threads) {
    if (kept.filledForEye != eye) {
        fillKeptLeaves(kept, spheres, eye, threads);
        return;
    }
    for (const std::int32_t k : moved)
        if (kept.slotOf[k] >= 0) kept.tree->leafSpheres[kept.slotOf[k]] = spheres.leafSphere(k);
}

}  // namespace

template <typename T>
std::shared_ptr<const SphereBvh<T>> sphereBvhFor(std::span<const glm::dvec3> centres,
                                                 std::span<const double> radii,
                                                 const SphereSet<T>& spheres, BvhCache* cache,
                                                 const glm::dvec3& frameOrigin, const Vec<T>& eye,
                                                 int threads) {
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
    const bool keptInFrame = keptAlone && kept.frameOrigin == frameOrigin;
    if (keptInFrame && cache->geometryRevision != 0 &&
        kept.geometryRevision == cache->geometryRevision) {
        refillKeptLeaves(kept, spheres, eye, {}, threads);
        ++cache->reuses;
        return kept.tree;
    }
    kept.geometryRevision = cache->geometryRevision;
    // A refit of the few moved spheres gives the boxes a whole refit would.
    const auto moved = keptInFrame ? movedSpheres(kept, centres, radii, threads) : std::nullopt;
    const bool refit = moved ? refitMoved(kept, *moved, centres, radii)
                             : keptAlone && refitSphereBvh(*kept.tree, centres, radii, threads);
    kept.frameOrigin = frameOrigin;
    if (refit && sahCost(*kept.tree, threads) <= BvhCache::kWornOut * kept.builtCost) {
        if (moved) {
            refillKeptLeaves(kept, spheres, eye, *moved, threads);
        } else {
            rememberFit(kept, centres, radii);
            fillKeptLeaves(kept, spheres, eye, threads);
        }
        ++cache->refits;
        return kept.tree;
    }
    kept.tree = std::make_shared<SphereBvh<T>>(buildSphereBvh<T>(centres, radii, build));
    fillKeptLeaves(kept, spheres, eye, threads);
    kept.spheres = radii.size();
    kept.builtCost = sahCost(*kept.tree, threads);
    indexKeptTree(kept, centres, radii, threads);
    ++cache->builds;
    return kept.tree;
}

#define WHITTED_BVH_REFIT(T)                                                                  \
    template bool refitSphereBvh<T>(SphereBvh<T>&, std::span<const glm::dvec3>,               \
                                    std::span<const double>, int);                            \
    template double sahCost<T>(const SphereBvh<T>&, int);                                     \
    template std::shared_ptr<const SphereBvh<T>> sphereBvhFor<T>(                             \
        std::span<const glm::dvec3>, std::span<const double>, const SphereSet<T>&, BvhCache*, \
        const glm::dvec3&, const Vec<T>&, int);
WHITTED_BVH_REFIT(float)
WHITTED_BVH_REFIT(double)
#undef WHITTED_BVH_REFIT

}  // namespace whitted
