// Building the sphere BVH (bvh.h): binned SAH over the spheres' boxes rounded
// outward to T (bvh_split.h), in two phases: the top levels level by level,
// each level's ranges on all cores, then the ranges below kJobSpheres as
// independent jobs on all cores, spliced into one flat array of nodes in a
// fixed order; or, for a lazy tree, each job when a ray first enters it
// (lazyJobRoot()). The refit of a built tree and the cache that keeps one are
// in bvh_refit.cpp.
#include "tracer/bvh.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>
#include <numeric>

#include "base/parallel_for.h"
#include "tracer/bvh_boxes.h"
#include "tracer/bvh_split.h"

namespace whitted {

namespace {

using namespace bvh_build;

template <typename T>
using RefArray = std::vector<Ref<T>, LargeBufferAllocator<Ref<T>>>;

// Splits are found by SAH up to this depth and at the median below it, which
// bounds the depth (kMaxBvhDepth) even for spheres piled on one spot.
constexpr int kSahDepth = 48;
// Cost of visiting a node against testing one sphere, for the SAH. A leaf's
// spheres lie side by side (SphereBvh::leafSpheres), so a sphere more in a leaf
// costs little beside a node more, whose box is another cache line. 5, with
// leaves of up to 8 (BvhBuildOptions), against 1 and 4: 3 to 4% more
// instructions and 10 to 13% fewer cache misses in a render, and 35 to 38 bytes per sphere in a
// float tree (59 to 62 in double) instead of 65 to 86 (docs/design/acceleration.md).
constexpr double kTraversalCost = 5.0;
// The split of a larger range is chosen from about this many of its spheres,
// evenly spaced: binning all of them read every sphere of the scene once per
// top level, and on fields from sparse to dense this sample moved the tree's
// SAH cost by at most 0.02% (docs/design/acceleration.md).
constexpr int kSplitSamples = 4096;
// Ranges with fewer spheres than this are built as one job on one thread; the
// levels above are split first, each level's ranges in parallel. Small enough to give two
// cores some dozens of jobs at 100k spheres, large enough that a job's set-up
// is nothing beside its work. Fixed, so the tree does not depend on the threads.
constexpr int kJobSpheres = 2048;

// nodes[1] of a tree: the root alone at 0, every pair of children then
// starts at an even index, and so shares a cache line (the traversal tests
// both when it enters their parent).
constexpr BvhNode kPadding{{0, 0, 0}, {0, 0, 0}, 0, 0};

// A part of the tree built on its own: the whole tree, or one job's range.
template <typename T>
struct Subtree {
    BvhArray<BvhNode> nodes;         // nodes[0] is its root
    BvhArray<std::int32_t> spheres;  // its leaves' spheres; leaves index into this
    int depth = 0;                   // its deepest leaf, counted from the whole tree's root
};

// A range of refs and the node that will hold it.
struct Range {
    int node, begin, end, depth;
    int size() const { return end - begin; }
};

// The ranges' indices, largest first (ties in order), for parallelFor.
std::vector<int> largestFirst(const std::vector<Range>& ranges) {
    std::vector<int> order(ranges.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return ranges[a].size() > ranges[b].size(); });
    return order;
}

template <typename T>
class Builder {
  public:
    Builder(RefArray<T>& refs, const BvhBuildOptions& options)
        : refs_(refs), bins_(std::clamp(options.bins, 2, bvh_build::kMaxBins)), options_(options) {}

    // A range's box, and how its refs were divided between two children.
    struct Division {
        bvh_build::LaneBox<T> box;
        int firstCount = 0;  // refs put first, for the first child; 0: the range is a leaf
        int axis = 0;
    };

    Division divide(const Range& r) const {
        Ref<T>* refs = refs_.data() + r.begin;
        const int n = r.size();
        const bvh_build::RangeBounds<T> bounds = bvh_build::rangeBounds(refs, n);
        Division d{bounds.box};
        // Splitting costs at least kTraversalCost: a range no larger is a
        // leaf whatever its best split, so that is not looked for.
        if (n <= std::min<double>(options_.maxLeafSize, kTraversalCost)) return d;
        // A small range gets a bin for every two spheres (at least 4): most
        // ranges are small, and their sweeps over mostly empty bins were
        // most of the build; against a bin a sphere, 13% less time at 1M
        // spheres for a tree 0.13% worse by the SAH (docs/design/acceleration.md).
        const bvh_build::Binning<T> map(std::min(bins_, std::max(4, n / 2)), bounds.centres);
        const bvh_build::Split best =
            r.depth < kSahDepth ? bvh_build::bestSplit(refs, n, map, std::max(1, n / kSplitSamples))
                                : bvh_build::Split{};
        if (best.axis >= 0) {
            const double splitCost = kTraversalCost + best.cost / double(bounds.box.halfArea());
            if (n <= options_.maxLeafSize && !(splitCost < n)) return d;
            d.firstCount = bvh_build::partitionRefs(refs, n, map, best);
            d.axis = best.axis;
        } else if (n > options_.maxLeafSize) {
            // Too deep, or every centre on one spot: halves by count.
            d.axis = bounds.centres.longestAxis();
            d.firstCount = bvh_build::medianSplit(refs, n, d.axis);
        }
        return d;
    }

    // Writes a divided range into its node: a leaf, or an inner node whose two
    // children are appended to `into`. Returns the children's ranges (none for a leaf).
    std::vector<Range> place(Subtree<T>& into, const Range& r, const Division& d) const {
        into.depth = std::max(into.depth, r.depth);
        BvhNode& node = into.nodes[r.node];
        storeBox(node, d.box);
        if (d.firstCount == 0) {
            makeLeaf(into, r);
            return {};
        }
        const int children = static_cast<int>(into.nodes.size());
        node.first = children;
        node.count = -1 - d.axis;
        into.nodes.resize(children + 2);
        const int mid = r.begin + d.firstCount;
        return {{children, r.begin, mid, r.depth + 1}, {children + 1, mid, r.end, r.depth + 1}};
    }

    // The whole subtree of a range, depth first, on this thread.
    void build(Subtree<T>& into, const Range& r) const {
        for (const Range& child : place(into, r, divide(r))) build(into, child);
    }

  private:
    // A leaf lists its spheres in index order: neighbours in the scene file
    // are often neighbours in memory too.
    void makeLeaf(Subtree<T>& into, const Range& r) const {
        BvhNode& leaf = into.nodes[r.node];
        leaf.first = static_cast<std::int32_t>(into.spheres.size());
        leaf.count = r.size();
        for (int i = r.begin; i < r.end; ++i) into.spheres.push_back(refs_[i].sphere());
        std::sort(into.spheres.begin() + leaf.first, into.spheres.end());
    }

    RefArray<T>& refs_;
    const int bins_;
    const BvhBuildOptions& options_;
};

// Copies a job's subtree's nodes into `nodes`: its root into nodes[root], the
// rest from nodes[nodeBase + 1] on, its leaves pointing from sphereBase on.
template <typename T>
void spliceNodes(BvhNode* nodes, int root, const Subtree<T>& part, std::int32_t nodeBase,
                 std::int32_t sphereBase) {
    const auto moved = [&](BvhNode n) {
        n.first += n.count > 0 ? sphereBase : nodeBase;
        return n;
    };
    nodes[root] = moved(part.nodes[0]);
    for (std::size_t i = 1; i < part.nodes.size(); ++i) nodes[nodeBase + i] = moved(part.nodes[i]);
}

// A job's subtree, on this thread. Room for the usual tree at once (a node
// for every two to three spheres), not by doubling: each growth copied and
// zeroed the nodes.
template <typename T>
Subtree<T> buildJob(const Builder<T>& builder, const Range& job) {
    Subtree<T> part;
    part.nodes.reserve(job.size());
    part.spheres.reserve(job.size());
    part.nodes.resize(1);
    builder.build(part, {0, job.begin, job.end, job.depth});
    return part;
}

// The top of the tree, level by level: the ranges of a level are divided in
// parallel, then placed in order, so the layout does not depend on the
// threads. Returns the ranges under kJobSpheres, left for buildJobs().
template <typename T>
std::vector<Range> buildTop(const Builder<T>& builder, Subtree<T>& tree, int count, int threads) {
    std::vector<Range> level = {{0, 0, count, 0}}, jobs;
    using Division = typename Builder<T>::Division;
    while (!level.empty()) {
        std::vector<Division> divisions(level.size());
        parallelFor(largestFirst(level), threads,
                    [&](int i) { divisions[i] = builder.divide(level[i]); });
        std::vector<Range> next;
        for (std::size_t i = 0; i < level.size(); ++i)
            for (const Range& child : builder.place(tree, level[i], divisions[i]))
                (child.size() < kJobSpheres ? jobs : next).push_back(child);
        level = std::move(next);
    }
    return jobs;
}

// The subtrees of the jobs, in parallel, then copied into the tree in job
// order, also in parallel (each job's block of the arrays is known once all
// are built).
template <typename T>
void buildJobs(const Builder<T>& builder, Subtree<T>& tree, const std::vector<Range>& jobs,
               int threads) {
    std::vector<Subtree<T>> parts(jobs.size());
    const std::vector<int> order = largestFirst(jobs);
    parallelFor(order, threads, [&](int k) { parts[k] = buildJob(builder, jobs[k]); });
    std::vector<std::int32_t> nodeBase(jobs.size()), sphereBase(jobs.size());
    std::size_t nodes = tree.nodes.size(), spheres = tree.spheres.size();
    for (std::size_t k = 0; k < jobs.size(); ++k) {
        nodeBase[k] = static_cast<std::int32_t>(nodes) - 1;
        sphereBase[k] = static_cast<std::int32_t>(spheres);
        nodes += parts[k].nodes.size() - 1;
        spheres += parts[k].spheres.size();
        tree.depth = std::max(tree.depth, parts[k].depth);
    }
    tree.nodes.resize(nodes);
    tree.spheres.resize(spheres);
    parallelFor(order, threads, [&](int k) {
        spliceNodes(tree.nodes.data(), jobs[k].node, parts[k], nodeBase[k], sphereBase[k]);
        std::copy(parts[k].spheres.begin(), parts[k].spheres.end(),
                  tree.spheres.begin() + sphereBase[k]);
    });
}

// The refs of the spheres in the tree, in index order, made in parallel by
// chunks (each chunk's place in the array counted first).
template <typename T>
RefArray<T> makeRefs(std::span<const glm::dvec3> centres, std::span<const double> radii,
                     const std::vector<char>& out, int threads) {
    const int n = static_cast<int>(radii.size());
    std::vector<int> firstRef(chunkCount(n));  // where each chunk's refs begin
    int kept = 0;
    for (int c = 0; c < chunkCount(n); ++c) {
        firstRef[c] = kept;
        const int begin = c * kSphereChunk, end = std::min(n, begin + kSphereChunk);
        kept += static_cast<int>(std::count(out.begin() + begin, out.begin() + end, 0));
    }
    RefArray<T> refs(kept);
    forEachChunk(n, threads, [&](int c, int begin, int end) {
        int next = firstRef[c];
        for (int i = begin; i < end; ++i)
            if (!out[i]) refs[next++] = sphereRef<T>(centres[i], radii[i], i);
    });
    return refs;
}

}  // namespace

// The jobs of a lazy tree, and what building one needs.
template <typename T>
struct LazyJobs {
    struct Job {
        Range range;
        std::int32_t nodeBase;    // its nodes' block: its root, a padding node, the rest
        std::int32_t sphereBase;  // its leaves' spheres' block
    };
    RefArray<T> refs;  // the jobs' ranges of them, still unsorted
    BvhBuildOptions options;
    std::vector<Job> jobs;
    std::unique_ptr<std::once_flag[]> once;  // one for each job
    // Set once a job is built: std::call_once itself sets up thread-local
    // state on every call, 1.6% of a render's time at a million spheres.
    std::unique_ptr<std::atomic<bool>[]> ready;
};

namespace {

// The tree's nodes, with the jobs' subtrees built, or, lazily, waiting under
// their nodes: those get their ranges' boxes and kLazyNode now, and each job
// blocks of the arrays large enough for any tree of its spheres (two nodes a
// sphere), which stay untouched pages, and so cost no memory, until the job
// is built.
template <typename T>
void buildTree(SphereBvh<T>& bvh, RefArray<T>&& refs, const BvhBuildOptions& options, int threads) {
    if (refs.empty()) return;
    Subtree<T> tree;
    tree.nodes.resize(2);
    tree.nodes[1] = kPadding;
    const Builder<T> builder(refs, options);
    const int count = static_cast<int>(refs.size());
    const std::vector<Range> jobs = count < kJobSpheres ? std::vector<Range>{{0, 0, count, 0}}
                                                        : buildTop(builder, tree, count, threads);
    if (!options.lazy || count < kJobSpheres) {
        buildJobs(builder, tree, jobs, threads);
        bvh.nodes = std::move(tree.nodes);
        bvh.leafSpheres.resize(tree.spheres.size());
        forChunks(static_cast<int>(tree.spheres.size()), threads,
                  [&](int i) { bvh.leafSpheres[i].index = tree.spheres[i]; });
        bvh.depth = tree.depth;
        return;
    }
    auto waiting = std::make_shared<LazyJobs<T>>();
    std::size_t nodes = tree.nodes.size(), spheres = 0;  // nodes: even, as a block must start
    for (const Range& job : jobs) {
        waiting->jobs.push_back(
            {job, static_cast<std::int32_t>(nodes), static_cast<std::int32_t>(spheres)});
        nodes += 2 * std::size_t(job.size());
        spheres += job.size();
    }
    parallelFor(largestFirst(jobs), threads, [&](int k) {
        BvhNode& node = tree.nodes[jobs[k].node];
        storeBox(node, bvh_build::rangeBounds(refs.data() + jobs[k].begin, jobs[k].size()).box);
        node.first = k;
        node.count = kLazyNode;
    });
    tree.nodes.resize(nodes);
    bvh.nodes = std::move(tree.nodes);
    bvh.leafSpheres.resize(spheres);
    bvh.depth = tree.depth;
    waiting->refs = std::move(refs);
    waiting->options = options;
    waiting->once = std::make_unique<std::once_flag[]>(jobs.size());
    waiting->ready = std::make_unique<std::atomic<bool>[]>(jobs.size());
    bvh.lazy = std::move(waiting);
}

}  // namespace

template <typename T>
SphereBvh<T> buildSphereBvh(std::span<const glm::dvec3> centres, std::span<const double> radii,
                            const BvhBuildOptions& options) {
    SphereBvh<T> bvh;
    const int threads = resolveThreadCount(options.threads);
    const std::vector<char> out = keptOut<T>(centres, radii, options, threads);
    for (int i = 0; i < static_cast<int>(radii.size()); ++i)
        if (out[i]) bvh.direct.push_back(i);
    buildTree(bvh, makeRefs<T>(centres, radii, out, threads), options, threads);
    return bvh;
}

template <typename T>
int lazyJobRoot(const SphereBvh<T>& bvh, int job, const SphereSet<T>& spheres) {
    LazyJobs<T>& lazy = *bvh.lazy;
    const typename LazyJobs<T>::Job& j = lazy.jobs[job];
    if (lazy.ready[job].load(std::memory_order_acquire)) return j.nodeBase;
    std::call_once(lazy.once[job], [&] {
        const Subtree<T> part = buildJob(Builder<T>(lazy.refs, lazy.options), j.range);
        // Readers hold the tree const, and read a job's blocks only after
        // this returns: `ready` and the once_flag order these writes before their reads.
        BvhNode* nodes = const_cast<BvhNode*>(bvh.nodes.data());
        LeafSphere<T>* leaves = const_cast<LeafSphere<T>*>(bvh.leafSpheres.data());
        spliceNodes(nodes, j.nodeBase, part, j.nodeBase + 1, j.sphereBase);
        for (std::size_t i = 0; i < part.spheres.size(); ++i)
            leaves[j.sphereBase + i] = spheres.leafSphere(part.spheres[i]);
        lazy.ready[job].store(true, std::memory_order_release);
    });
    return j.nodeBase;
}

template <typename T>
int lazyJobsBuilt(const SphereBvh<T>& bvh) {
    if (!bvh.lazy) return 0;
    const LazyJobs<T>& lazy = *bvh.lazy;
    return static_cast<int>(std::count_if(lazy.ready.get(), lazy.ready.get() + lazy.jobs.size(),
                                          [](const std::atomic<bool>& r) { return r.load(); }));
}

template <typename T>
int lazyJobCount(const SphereBvh<T>& bvh) {
    return bvh.lazy ? static_cast<int>(bvh.lazy->jobs.size()) : 0;
}

#define WHITTED_BVH(T)                                                                            \
    template SphereBvh<T> buildSphereBvh<T>(std::span<const glm::dvec3>, std::span<const double>, \
                                            const BvhBuildOptions&);                              \
    template int lazyJobRoot<T>(const SphereBvh<T>&, int, const SphereSet<T>&);                   \
    template int lazyJobsBuilt<T>(const SphereBvh<T>&);                                           \
    template int lazyJobCount<T>(const SphereBvh<T>&);
WHITTED_BVH(float)
WHITTED_BVH(double)
#undef WHITTED_BVH

}  // namespace whitted
