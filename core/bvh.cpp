// Building the sphere BVH (bvh.h): binned SAH over the spheres' boxes in double,
// written into a flat array of nodes with boxes rounded outward to T.
#include "bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace whitted {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Splits are found by SAH up to this depth and at the median below it, which
// bounds the depth (kMaxBvhDepth) even for spheres piled on one spot.
constexpr int kSahDepth = 48;
// Cost of visiting a node against testing one sphere, for the SAH. A packet's
// box test is about half a sphere test; 1 keeps leaves a little fuller, which
// measured no slower (docs/performance.md).
constexpr double kTraversalCost = 1.0;

struct Bounds {
    glm::dvec3 lo{kInf}, hi{-kInf};

    void grow(const Bounds& b) {
        for (int i = 0; i < 3; ++i) {
            lo[i] = std::min(lo[i], b.lo[i]);
            hi[i] = std::max(hi[i], b.hi[i]);
        }
    }
    void grow(const glm::dvec3& p) { grow(Bounds{p, p}); }
    bool empty() const { return !(lo.x <= hi.x); }
    double extent(int axis) const { return empty() ? 0.0 : hi[axis] - lo[axis]; }
    int longestAxis() const {
        const int xy = extent(0) >= extent(1) ? 0 : 1;
        return extent(xy) >= extent(2) ? xy : 2;
    }
    // Half the surface area: what the SAH weighs a child's chance of a visit by.
    double halfArea() const {
        const double x = extent(0), y = extent(1), z = extent(2);
        return x * y + y * z + z * x;
    }
};

struct Ref {
    Bounds box;
    glm::dvec3 centre;
    std::int32_t sphere;
};

Bounds sphereBounds(const glm::dvec3& c, double r) {
    return {c - r, c + r};
}

// The largest |coordinate| + radius a sphere in the tree may have: the margin
// argument in bvh_traverse.h needs squares of such numbers to stay finite in T
// (1e34 in float, 1e300 in double). Beyond it a sphere is tested directly.
template <typename T>
constexpr double kTreeReach = sizeof(T) == sizeof(float) ? 1e17 : 1e150;

// x rounded to T towards -infinity / +infinity. The rounded value goes through
// a volatile, as in SphereSet::split: GCC's SLP vectoriser has been seen
// dropping double(T(x)) round trips.
template <typename T>
T roundedDown(double x) {
    const volatile T t = static_cast<T>(x);
    return double(t) > x ? std::nextafter(T(t), -std::numeric_limits<T>::infinity()) : T(t);
}
template <typename T>
T roundedUp(double x) {
    const volatile T t = static_cast<T>(x);
    return double(t) < x ? std::nextafter(T(t), std::numeric_limits<T>::infinity()) : T(t);
}

template <typename T>
void setBox(BvhNode<T>& node, const Bounds& b) {
    for (int i = 0; i < 3; ++i) {
        node.lo[i] = roundedDown<T>(b.lo[i]);
        node.hi[i] = roundedUp<T>(b.hi[i]);
    }
}

// Which spheres stay out of the tree (bvh.h, SphereBvh::direct): first any a
// tree in T cannot bound, then, largest first, each one far larger than all
// the spheres smaller than it together.
template <typename T>
std::vector<bool> keptOut(const std::vector<glm::dvec3>& centres, const std::vector<double>& radii,
                          const BvhBuildOptions& options) {
    const int n = static_cast<int>(radii.size());
    std::vector<bool> out(n, false);
    std::vector<int> order;
    for (int i = 0; i < n; ++i) {
        const glm::dvec3& c = centres[i];
        const double reach = std::max({std::fabs(c.x), std::fabs(c.y), std::fabs(c.z)}) + radii[i];
        if (reach < kTreeReach<T>)
            order.push_back(i);
        else
            out[i] = true;
    }
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return radii[a] > radii[b]; });
    const int m = static_cast<int>(order.size());
    std::vector<Bounds> smaller(m + 1);  // smaller[i]: the box of order[i ..]
    for (int i = m - 1; i >= 0; --i) {
        smaller[i] = smaller[i + 1];
        smaller[i].grow(sphereBounds(centres[order[i]], radii[order[i]]));
    }
    for (int i = 0; i < std::min(options.maxDirect, m - 1); ++i) {
        const Bounds& rest = smaller[i + 1];
        if (!(2.0 * radii[order[i]] > options.hugeRatio * rest.extent(rest.longestAxis()))) break;
        out[order[i]] = true;
    }
    return out;
}

// A candidate split: refs whose centre falls in bins [0, bin] go to the first child.
struct Split {
    int axis = -1;
    int bin = 0;
    double cost = kInf;  // sum over both children of half area times spheres
};

// Bins centres along one axis: the same mapping for costing and partitioning.
struct Binning {
    int bins;
    double lo, scale;
    Binning(int bins, const Bounds& centres, int axis)
        : bins(bins), lo(centres.lo[axis]), scale(bins / centres.extent(axis)) {}
    int operator()(double x) const {
        return std::clamp(static_cast<int>((x - lo) * scale), 0, bins - 1);
    }
};

template <typename T>
class Builder {
  public:
    Builder(std::vector<Ref> refs, const BvhBuildOptions& options, SphereBvh<T>& out)
        : refs_(std::move(refs)), options_(options), out_(out) {}

    void run() {
        if (refs_.empty()) return;
        out_.nodes.emplace_back();
        out_.spheres.reserve(refs_.size());
        build(0, 0, static_cast<int>(refs_.size()), 0);
    }

  private:
    void build(int node, int begin, int end, int depth) {
        out_.depth = std::max(out_.depth, depth);
        Bounds box, centres;
        for (int i = begin; i < end; ++i) {
            box.grow(refs_[i].box);
            centres.grow(refs_[i].centre);
        }
        setBox(out_.nodes[node], box);
        const int n = end - begin;
        if (n == 1) return makeLeaf(node, begin, end);
        int axis = centres.longestAxis();
        int mid;
        const Split split = depth < kSahDepth ? bestSplit(begin, end, centres) : Split{};
        if (split.axis >= 0) {
            const double leafCost = n;
            const double splitCost = kTraversalCost + split.cost / box.halfArea();
            if (n <= options_.maxLeafSize && !(splitCost < leafCost))
                return makeLeaf(node, begin, end);
            axis = split.axis;
            const Binning bin(options_.bins, centres, axis);
            mid = static_cast<int>(
                std::partition(refs_.begin() + begin, refs_.begin() + end,
                               [&](const Ref& r) { return bin(r.centre[axis]) <= split.bin; }) -
                refs_.begin());
        } else {
            // Too deep, or every centre on one spot: halves by count.
            if (n <= options_.maxLeafSize) return makeLeaf(node, begin, end);
            mid = begin + n / 2;
            std::nth_element(
                refs_.begin() + begin, refs_.begin() + mid, refs_.begin() + end,
                [axis](const Ref& a, const Ref& b) { return a.centre[axis] < b.centre[axis]; });
        }
        const int children = static_cast<int>(out_.nodes.size());
        out_.nodes.resize(children + 2);
        out_.nodes[node].first = children;
        out_.nodes[node].count = -1 - axis;
        build(children, begin, mid, depth + 1);
        build(children + 1, mid, end, depth + 1);
    }

    // The cheapest SAH split over all three axes; axis -1 when the centres
    // coincide (or the box has no area to weigh children by).
    Split bestSplit(int begin, int end, const Bounds& centres) const {
        const int bins = options_.bins;
        Split best;
        std::vector<Bounds> binBox(bins), right(bins);
        std::vector<int> binCount(bins), rightCount(bins);
        for (int axis = 0; axis < 3; ++axis) {
            const Binning bin(bins, centres, axis);
            if (!(centres.extent(axis) > 0.0) || !std::isfinite(bin.scale)) continue;
            std::fill(binBox.begin(), binBox.end(), Bounds{});
            std::fill(binCount.begin(), binCount.end(), 0);
            for (int i = begin; i < end; ++i) {
                const int b = bin(refs_[i].centre[axis]);
                binBox[b].grow(refs_[i].box);
                ++binCount[b];
            }
            right[bins - 1] = binBox[bins - 1];
            rightCount[bins - 1] = binCount[bins - 1];
            for (int b = bins - 2; b >= 0; --b) {
                right[b] = right[b + 1];
                right[b].grow(binBox[b]);
                rightCount[b] = rightCount[b + 1] + binCount[b];
            }
            Bounds left;
            int leftCount = 0;
            for (int b = 0; b + 1 < bins; ++b) {
                left.grow(binBox[b]);
                leftCount += binCount[b];
                if (leftCount == 0 || rightCount[b + 1] == 0) continue;
                const double cost =
                    left.halfArea() * leftCount + right[b + 1].halfArea() * rightCount[b + 1];
                if (cost < best.cost) best = {axis, b, cost};
            }
        }
        return best;
    }

    // A leaf lists its spheres in index order: neighbours in the scene file
    // are often neighbours in memory too.
    void makeLeaf(int node, int begin, int end) {
        BvhNode<T>& leaf = out_.nodes[node];
        leaf.first = static_cast<std::int32_t>(out_.spheres.size());
        leaf.count = end - begin;
        for (int i = begin; i < end; ++i) out_.spheres.push_back(refs_[i].sphere);
        std::sort(out_.spheres.begin() + leaf.first, out_.spheres.end());
    }

    std::vector<Ref> refs_;
    const BvhBuildOptions& options_;
    SphereBvh<T>& out_;
};

}  // namespace

template <typename T>
SphereBvh<T> buildSphereBvh(const std::vector<glm::dvec3>& centres,
                            const std::vector<double>& radii, const BvhBuildOptions& options) {
    SphereBvh<T> bvh;
    const std::vector<bool> out = keptOut<T>(centres, radii, options);
    std::vector<Ref> refs;
    refs.reserve(radii.size());
    for (int i = 0; i < static_cast<int>(radii.size()); ++i) {
        if (out[i])
            bvh.direct.push_back(i);
        else
            refs.push_back({sphereBounds(centres[i], radii[i]), centres[i], i});
    }
    Builder<T>(std::move(refs), options, bvh).run();
    return bvh;
}

template SphereBvh<float> buildSphereBvh<float>(const std::vector<glm::dvec3>&,
                                                const std::vector<double>&, const BvhBuildOptions&);
template SphereBvh<double> buildSphereBvh<double>(const std::vector<glm::dvec3>&,
                                                  const std::vector<double>&,
                                                  const BvhBuildOptions&);

}  // namespace whitted
