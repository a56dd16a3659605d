// One step of the sphere BVH's build (bvh.cpp): the box of a range of spheres
// and the binned-SAH split of that range in two. Internal to bvh.cpp.
//
// Boxes are kept in T, rounded outward from the spheres' double bounds once,
// when the refs are made: rounding outward is monotone, so the union of rounded
// boxes is the rounded union, and each node's box is what rounding its exact
// box would give. Each box is two vectors of four lanes (x, y, z and a spare
// one), so that growing a box is two vector instructions: the binning loop is
// most of the build, and with scalar min and max it took four times as long.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace whitted::bvh_build {

// x, y, z and a spare lane, as one SSE (float) or AVX (double) register. The
// attribute cannot take a template parameter, hence the specialisations.
template <typename T>
struct FourLanes;
template <>
struct FourLanes<float> {
    typedef float type __attribute__((vector_size(16)));
};
template <>
struct FourLanes<double> {
    typedef double type __attribute__((vector_size(32)));
};
template <typename T>
using Lanes = typename FourLanes<T>::type;
using LaneInts = std::int32_t __attribute__((vector_size(4 * sizeof(std::int32_t))));

template <typename T>
constexpr Lanes<T> kInfLanes = Lanes<T>{} + std::numeric_limits<T>::infinity();

template <typename T>
struct LaneBox {
    Lanes<T> lo = kInfLanes<T>, hi = -kInfLanes<T>;

    void grow(Lanes<T> l, Lanes<T> h) {
        lo = l < lo ? l : lo;
        hi = h > hi ? h : hi;
    }
    void grow(const LaneBox& b) { grow(b.lo, b.hi); }
    bool empty() const { return !(lo[0] <= hi[0]); }
    double extent(int a) const { return empty() ? 0.0 : double(hi[a]) - double(lo[a]); }
    int longestAxis() const {
        const int xy = extent(0) >= extent(1) ? 0 : 1;
        return extent(xy) >= extent(2) ? xy : 2;
    }
    // Half the surface area: what the SAH weighs a child's chance of a visit
    // by. In T: the tree's reach (bvh.cpp) keeps the products finite.
    T halfArea() const {
        const Lanes<T> d = hi - lo;
        return d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
    }
};

// A sphere as the build sees it: its box, already rounded outward to T. The
// spare lanes hold the sphere's index, 16 bits in each (exact in any T, and
// never a denormal to slow the arithmetic on the other lanes).
template <typename T>
struct Ref {
    Lanes<T> lo, hi;

    Ref() = default;  // uninitialised: made in parallel into memory from mmap
    Ref(Lanes<T> l, Lanes<T> h, std::int32_t sphere) : lo(l), hi(h) {
        lo[3] = static_cast<T>(sphere & 0xffff);
        hi[3] = static_cast<T>(sphere >> 16);
    }
    std::int32_t sphere() const {
        return static_cast<std::int32_t>(lo[3]) | static_cast<std::int32_t>(hi[3]) << 16;
    }
    // Twice the box's centre: binning needs only an order along each axis.
    Lanes<T> centre2() const { return lo + hi; }
};

// The box of a range and the box of its (doubled) centres.
template <typename T>
struct RangeBounds {
    LaneBox<T> box, centres;
};

template <typename T>
RangeBounds<T> rangeBounds(const Ref<T>* refs, int count) {
    RangeBounds<T> b;
    for (int i = 0; i < count; ++i) {
        b.box.grow(refs[i].lo, refs[i].hi);
        const Lanes<T> c = refs[i].centre2();
        b.centres.grow(c, c);
    }
    return b;
}

// More bins measured no better trees on the benchmark's fields and cost time.
inline constexpr int kMaxBins = 16;

// Bins centres along the three axes at once: the same mapping for costing and
// partitioning. An axis whose centres coincide (or whose scale T cannot hold)
// maps everything to bin 0 and is not split along.
template <typename T>
struct Binning {
    int bins;
    Lanes<T> lo, scale = {};
    bool usable[3];

    Binning(int bins, const LaneBox<T>& centres) : bins(bins), lo(centres.lo) {
        for (int a = 0; a < 3; ++a) {
            const T s = static_cast<T>(bins / centres.extent(a));
            usable[a] = centres.extent(a) > 0.0 && std::isfinite(s) && s > T(0);
            scale[a] = usable[a] ? s : T(0);
        }
    }
    LaneInts operator()(const Ref<T>& r) const {
        const LaneInts b = __builtin_convertvector((r.centre2() - lo) * scale, LaneInts);
        const LaneInts last = LaneInts{} + (bins - 1);
        const LaneInts low = b < 0 ? LaneInts{} : b;
        return low > last ? last : low;
    }
};

// A candidate split: refs whose centre falls in bins [0, bin] go to the first child.
struct Split {
    int axis = -1;
    int bin = 0;
    double cost = std::numeric_limits<double>::infinity();  // sum of half area times spheres
};

// The bins of one range along the three axes. Only the range's bins are set
// to empty, not all kMaxBins: most ranges are small, and setting every bin
// cost as much as binning their refs.
template <typename T>
struct Bins {
    Lanes<T> lo[3][kMaxBins], hi[3][kMaxBins];
    int count[3][kMaxBins];

    explicit Bins(int bins) {
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < bins; ++b) {
                lo[a][b] = kInfLanes<T>;
                hi[a][b] = -kInfLanes<T>;
                count[a][b] = 0;
            }
    }
    void add(const Ref<T>& r, LaneInts bin) {
        for (int a = 0; a < 3; ++a) {
            const int b = bin[a];
            lo[a][b] = r.lo < lo[a][b] ? r.lo : lo[a][b];
            hi[a][b] = r.hi > hi[a][b] ? r.hi : hi[a][b];
            ++count[a][b];
        }
    }
};

// The SAH cost of one side of a split; infinite when the side is empty, so
// that no split leaving a side empty is chosen.
template <typename T>
double sideCost(const LaneBox<T>& box, int count) {
    const double cost = double(box.halfArea()) * count;
    return count == 0 ? std::numeric_limits<double>::infinity() : cost;
}

// The cheapest SAH split over all three axes, binned in one pass over the
// range; axis -1 when the centres coincide. Every split is costed, with no
// branch on empty bins (which bins are empty is a coin toss in the small
// ranges that are most of a build, and those branches took half the sweep):
// a split just after an empty bin costs exactly what the one before it does,
// and the first of equal splits wins, axis by axis, bin by bin.
// With a stride above 1, only every stride-th ref is binned: the costs are
// then estimates, whose best split still leaves refs on both sides.
template <typename T>
Split bestSplit(const Ref<T>* refs, int count, const Binning<T>& map, int stride = 1) {
    Bins<T> bins(map.bins);
    for (int i = 0; i < count; i += stride) bins.add(refs[i], map(refs[i]));
    const int n = map.bins;
    double rightCost[kMaxBins][3];  // [b][a]: the cost of bins [b, n) along axis a
    LaneBox<T> side[3];
    int sideCount[3] = {0, 0, 0};
    for (int b = n - 1; b > 0; --b)
        for (int a = 0; a < 3; ++a) {
            side[a].grow(bins.lo[a][b], bins.hi[a][b]);
            sideCount[a] += bins.count[a][b];
            rightCost[b][a] = sideCost(side[a], sideCount[a]);
        }
    double cost[3][kMaxBins];  // [a][b]: bins [0, b] against bins (b, n)
    for (int a = 0; a < 3; ++a) side[a] = {}, sideCount[a] = 0;
    for (int b = 0; b + 1 < n; ++b)
        for (int a = 0; a < 3; ++a) {
            side[a].grow(bins.lo[a][b], bins.hi[a][b]);
            sideCount[a] += bins.count[a][b];
            cost[a][b] = sideCost(side[a], sideCount[a]) + rightCost[b + 1][a];
        }
    Split best;
    for (int a = 0; a < 3; ++a)
        for (int b = 0; map.usable[a] && b + 1 < n; ++b)
            if (cost[a][b] < best.cost) best = {a, b, cost[a][b]};
    return best;
}

// Whether a ref goes to the split's first child.
template <typename T>
bool inFirstChild(const Ref<T>& r, const Binning<T>& map, const Split& split) {
    return map(r)[split.axis] <= split.bin;
}

// Lomuto's scheme without a branch on the side (every ref swapped): which side
// a ref goes to is a coin toss near the top of the tree, and std::partition's
// mispredicted branches took a third of the build. Each swap stores to the
// place the next one loads from, so a ref costs a store's round trip: used
// for the few refs partitionRefs() leaves.
template <typename T>
int lomutoPartition(Ref<T>* refs, int count, const Binning<T>& map, const Split& split) {
    int firstCount = 0;
    for (int i = 0; i < count; ++i) {
        const Ref<T> r = refs[i];
        const bool first = inFirstChild(r, map, split);
        refs[i] = refs[firstCount];
        refs[firstCount] = r;
        firstCount += first;
    }
    return firstCount;
}

// Puts the refs of the split's first child first; returns how many there are.
// Blocks of refs from both ends are classified without a branch, each
// noting where its misplaced refs lie, and those are swapped in pairs (the
// block partition of Edelkamp and Weiss's BlockQuicksort): every ref is read
// once, only misplaced ones move, and no store waits on the one before:
// against lomutoPartition() alone, 2.2 times as fast on 2,000 refs and 1.8
// times on a million. What is left between the blocks, fewer than three
// blocks' refs, goes to lomutoPartition().
template <typename T>
int partitionRefs(Ref<T>* refs, int count, const Binning<T>& map, const Split& split) {
    constexpr int kBlock = 64;
    std::uint8_t misplacedLeft[kBlock], misplacedRight[kBlock];
    int left = 0, right = count;  // [0, left): first child; [right, count): second
    int leftCount = 0, rightCount = 0, leftNext = 0, rightNext = 0;
    while (right - left > 2 * kBlock) {
        if (leftCount == 0) {
            leftNext = 0;
            for (int i = 0; i < kBlock; ++i) {
                misplacedLeft[leftCount] = static_cast<std::uint8_t>(i);
                leftCount += !inFirstChild(refs[left + i], map, split);
            }
        }
        if (rightCount == 0) {
            rightNext = 0;
            for (int i = 0; i < kBlock; ++i) {
                misplacedRight[rightCount] = static_cast<std::uint8_t>(i);
                rightCount += inFirstChild(refs[right - 1 - i], map, split);
            }
        }
        const int swaps = std::min(leftCount, rightCount);
        for (int k = 0; k < swaps; ++k)
            std::swap(refs[left + misplacedLeft[leftNext + k]],
                      refs[right - 1 - misplacedRight[rightNext + k]]);
        leftCount -= swaps, rightCount -= swaps;
        leftNext += swaps, rightNext += swaps;
        if (leftCount == 0) left += kBlock;
        if (rightCount == 0) right -= kBlock;
    }
    return left + lomutoPartition(refs + left, right - left, map, split);
}

// Halves a range by count along an axis: for ranges SAH cannot split.
template <typename T>
int medianSplit(Ref<T>* refs, int count, int axis) {
    const int mid = count / 2;
    std::nth_element(refs, refs + mid, refs + count, [axis](const Ref<T>& x, const Ref<T>& y) {
        return x.centre2()[axis] < y.centre2()[axis];
    });
    return mid;
}

}  // namespace whitted::bvh_build
