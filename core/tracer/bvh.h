// A bounding volume hierarchy over the scene's spheres, so that a ray
// tests the few spheres near it instead of every one. Built once per render by
// code compiled with the project's flags, then read by whichever tracing kernel
// runs (kernel_dispatch.h); the traversal, compiled per instruction set, is in
// bvh_traverse.h. Plain values and free functions; no Qt.
//
// The tree only decides which spheres a ray is tested against; the test itself
// is the brute-force one (ray_packet.h), so a render with the tree equals the
// brute-force render bit for bit (tests/core/test_bvh.cpp). For that, a box
// must never exclude a sphere whose test would report a hit: the boxes are
// rounded outward to float here, and the traversal widens them further by a margin
// that covers the rounding errors of the sphere test (bvh_traverse.h).
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "base/large_buffer_allocator.h"
#include "tracer/sphere_set.h"

namespace whitted {

// One node of the flattened binary tree: 32 bytes, two to a cache line.
// Left uninitialised when made: the build writes every field, and the pages
// of a large tree are then first touched by the threads that fill them.
//
// The box is in float for double trees too, rounded outward from the double
// box, as Embree stores its boxes: 56-byte double nodes made the double tree
// 75 bytes per sphere, and double renders measured no slower with float boxes
// (docs/design/acceleration.md). A box in float only ever holds more; the traversal's
// arithmetic stays in T.
struct BvhNode {
    float lo[3], hi[3];  // the box [lo, hi], holding every sphere below, rounded outward
    // Inner node: `first` is the index of its first child, an even one, the
    // second child is first + 1, and count == -1 - axis, the axis the children
    // were split along (the first child holds the lower centres). Leaf: its
    // spheres are SphereBvh::leafSpheres[first, first + count), count >= 1.
    // count == 0: nodes[1], which only pads the root's cache line.
    // count == kLazyNode: a lazy tree's subtree not built until a ray needs it
    // (BvhBuildOptions::lazy); `first` is its job, the box already its own.
    std::int32_t first;
    std::int32_t count;
};

inline constexpr std::int32_t kLazyNode = std::numeric_limits<std::int32_t>::min();

// The tree's arrays: large ones come from mmap (large_buffer_allocator.h).
template <typename T>
using BvhArray = std::vector<T, LargeBufferAllocator<T>>;

// What a lazy tree keeps to build its subtrees on demand (bvh.cpp).
template <typename T>
struct LazyJobs;

template <typename T>
struct SphereBvh {
    // Moved, never copied: a lazy tree's subtrees are built into the arrays
    // it was made with.
    SphereBvh() = default;
    SphereBvh(SphereBvh&&) = default;
    SphereBvh& operator=(SphereBvh&&) = default;
    SphereBvh(const SphereBvh&) = delete;
    SphereBvh& operator=(const SphereBvh&) = delete;

    // nodes[0] is the root, nodes[1] padding; empty when no sphere is in the tree.
    // Siblings share a cache line (the array is cache-line aligned).
    BvhArray<BvhNode> nodes;
    // The leaves' spheres, leaf after leaf, each with what the sphere test
    // reads of it: the build sets every index, sphereBvhFor() the rest from the
    // scene's SphereSet (which alone knows the camera).
    BvhArray<LeafSphere<T>> leafSpheres;
    // Spheres kept out of the tree and tested on every ray: huge ones such as a
    // floor (their box would swell every node above them, and the margin with
    // it), and any whose box T cannot hold. In index order.
    std::vector<std::int32_t> direct;
    int depth = 0;  // the longest path from the root to a leaf, in edges (of a
                    // lazy tree: to its subtrees not yet built)
    // Null for a tree built whole; else its subtrees still to build, each
    // under a kLazyNode (bvh.cpp).
    std::shared_ptr<LazyJobs<T>> lazy;
};

struct BvhBuildOptions {
    int bins = 16;        // SAH candidate planes per axis: bins - 1
    int maxLeafSize = 8;  // a node with more spheres is always split
    // A sphere whose diameter is more than hugeRatio times the longest side of
    // the box of all smaller spheres stays out of the tree (the seed's floor:
    // 199998 against a few units). At most maxDirect of them: each costs every ray.
    double hugeRatio = 4.0;
    int maxDirect = 8;
    // Threads building the lower levels; 0: one per core. The tree is the same
    // for any number.
    int threads = 0;
    // Build only the top of the tree now, and each subtree of fewer than a few
    // thousand spheres when a ray first enters it (lazyJobRoot()): a render
    // of a million balls on a floor enters fewer than two thirds of them
    // (docs/design/acceleration.md). The tree then walked is the whole tree's.
    bool lazy = false;
};

// The deepest tree buildSphereBvh() makes: past depth 48 it splits at the
// median, so 2^31 spheres stay below it. Traversal stacks are this deep.
inline constexpr int kMaxBvhDepth = 96;

// A binned-SAH tree over spheres given by their centres and radii in double
// (the prepared scene's frame). Sphere i of the tree is sphere i of the scene.
template <typename T>
SphereBvh<T> buildSphereBvh(std::span<const glm::dvec3> centres, std::span<const double> radii,
                            const BvhBuildOptions& options = {});

// The root of a lazy tree's subtree `job`, its nodes and leaves built first if
// no ray has entered it yet, from `spheres` (the SphereSet the tree was made
// for). Safe to call from several threads at once: one builds, the others wait.
template <typename T>
int lazyJobRoot(const SphereBvh<T>& bvh, int job, const SphereSet<T>& spheres);

// How many of a lazy tree's subtrees have been built, and how many it has.
template <typename T>
int lazyJobsBuilt(const SphereBvh<T>& bvh);
template <typename T>
int lazyJobCount(const SphereBvh<T>& bvh);

// Recomputes every box of `bvh` for its spheres' new centres and radii,
// keeping the tree's shape: after an edit that moved or resized spheres (or a
// camera move, which moves every sphere of the camera-centred frame), a pass
// over the nodes instead of a build. The same spheres must be given (same
// count, and the direct ones still there). Returns false, and leaves `bvh`
// as it was, when a sphere of the tree now lies beyond what a tree in T can
// bound, or when `bvh` was built lazily: build anew then. On up to `threads`
// threads (0: every core).
template <typename T>
bool refitSphereBvh(SphereBvh<T>& bvh, std::span<const glm::dvec3> centres,
                    std::span<const double> radii, int threads = 0);

// The tree's SAH cost, not divided by the root's area (a sphere grown huge
// also grows the root): the nodes' half areas, a leaf's times its spheres.
// Compared between refits of one tree: how far they have worn it.
template <typename T>
double sahCost(const SphereBvh<T>& bvh, int threads = 0);

// The trees a renderer built last, one per precision, so that the next render
// of an edited scene refits instead of building (the editor's render worker
// keeps one; a render uses it from one thread). A refit tree whose SAH cost has
// grown past kWornOut times its build's is built anew.
struct BvhCache {
    static constexpr double kWornOut = 1.5;
    template <typename T>
    struct Entry {
        std::shared_ptr<SphereBvh<T>> tree;
        std::size_t spheres = 0;
        double builtCost = 0;
        // What the tree was made or last refit for: the caller's revision (0:
        // none given) and the frame the centres were taken in.
        std::uint64_t geometryRevision = 0;
        glm::dvec3 frameOrigin{0.0};
        // So that an edit of a few spheres refits and refills only where they
        // lie (at a million spheres, whole passes were most of preparing a
        // render): the centres and radii the tree was last fit to, each
        // sphere's leaf and slot in leafSpheres (-1: not in the tree), each
        // node's parent (-1: the root), and the eye the leaves' copies were
        // last filled for.
        std::vector<glm::dvec3> fitCentres;
        std::vector<double> fitRadii;
        std::vector<std::int32_t> leafOf, slotOf, parentOf;
        std::optional<Vec<T>> filledForEye;
    };
    Entry<float> floats;
    Entry<double> doubles;
    // The caller's count of changes to the spheres' centres, radii and order,
    // set before a render (the editor's document keeps one); 0: unknown. A tree
    // kept for the same nonzero count, in the same frame, is used as it is:
    // giving a material to spheres moves none of them, and the refit was a
    // third of the preparing of a million spheres.
    std::uint64_t geometryRevision = 0;
    int builds = 0, refits = 0, reuses = 0;  // what the renders did, for tests and benchmarks

    template <typename T>
    Entry<T>& entry() {
        if constexpr (sizeof(T) == sizeof(float))
            return floats;
        else
            return doubles;
    }
};

// The tree for these spheres: the one in `cache` as it is when the cache's
// geometryRevision and `frameOrigin` are those it was kept for; else that one
// refit when it holds as many spheres and the refit does not wear it out (where
// few spheres moved, only their leaves and the nodes above them); else built
// (and kept there). Without a cache, built lazily (BvhBuildOptions::lazy).
// Its leafSpheres are `spheres`' values, which must be the same spheres as
// centres and radii (taken in the frame at `frameOrigin`, their camera terms
// for the eye at `eye`). On up to `threads` threads (0: every core).
template <typename T>
std::shared_ptr<const SphereBvh<T>> sphereBvhFor(std::span<const glm::dvec3> centres,
                                                 std::span<const double> radii,
                                                 const SphereSet<T>& spheres, BvhCache* cache,
                                                 const glm::dvec3& frameOrigin, const Vec<T>& eye,
                                                 int threads = 0);

}  // namespace whitted
