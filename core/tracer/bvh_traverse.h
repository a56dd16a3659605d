// Packets of rays through a SphereBvh (bvh.h): the nearest hit and the shadow
// transmittance of ray_packet.h, from the spheres whose boxes a ray meets.
//
// Same image as brute force, bit for bit (tests/core/test_bvh.cpp):
//  * every sphere a ray is tested against goes through intersectPacket() with
//    the formulas of packetClosestHits() and packetTransmittance(); a lane's
//    result does not depend on which other lanes are active;
//  * the nearest hit is the least (t, sphere index), which is what brute
//    force's strict "t < best" in index order keeps, whatever order the tree
//    visits the spheres in;
//  * transmittance multiplies the crossed spheres' transparencies in index
//    order, as brute force does (a product rounds differently in another
//    order), and stops early only at an opaque sphere, where it is 0 either way;
//  * a box never drops a sphere whose test would report a hit (kBvhSlack below).
//
// Lanes go through the tree together, masked as they leave the boxes. Each
// lane of reflected, refracted and shadow packets alone through the tree took
// 1.7 to 3 times as long (docs/design/acceleration.md): a sphere test costs one
// vector operation however few lanes it serves.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "tracer/bvh.h"
#include "tracer/isa_namespace.h"
#include "tracer/ray_packet.h"
#include "tracer/simd.h"
#include "tracer/sphere_set.h"

namespace whitted {

inline namespace WHITTED_ISA_NAMESPACE {

// How far a box is widened for a ray: kBvhSlack * (|o|_1 + reach), o the ray's
// origin and reach the sum over axes of the root box's largest |coordinate|,
// which is at least |c|_1 + r for every sphere (c, r) in the tree. Each node's
// own reach would do, and is narrower near the eye, but working it out was 19
// of a box test's 74 instructions; the root's is worked out once a packet
// (bench_scaling, 100k: ours over Embree 4 to 8 % lower on four layouts).
//
// Why that covers the sphere test: intersectPacket() works with f = o - c, so
// each of its roundings is relative to |f|, |b| <= |f|, r or r^2; a reported
// root t then puts the exact point o + t d within a few eps (|f| + r) of the
// ball (a grazing line is accepted when r^2 - |perp|^2 rounds to >= 0, i.e.
// within eps |f| of the ball; a root's own error moves the point along the
// ray by eps |f| (1 + r / sqrt(disc)), which changes its distance from the
// centre only by eps |f| r). |f| <= |o|_1 + |c|_1. The test measures the
// constant below 1 (0.84 in float, 0.91 in double: HitsLieWithinTheMargin,
// radii 1e-4 to 1e6, centres to 1e7, grazing lines); the slab test's own
// roundings (the subtraction, the margin, 1/d, the product) are another few
// eps of the same sizes. 64 leaves a wide safety factor and costs nothing
// that matters: 64 eps is 8e-6 of the scene's reach in float.
//
// The argument needs squares of coordinates to be finite in T: spheres beyond
// kTreeReach (bvh.cpp) stay out of the tree, and packets whose origins lie
// beyond kBvhOriginReach take the brute-force loop.
template <typename T>
inline constexpr T kBvhSlack = T(64) * std::numeric_limits<T>::epsilon();
template <typename T>
inline constexpr T kBvhOriginReach = sizeof(T) == sizeof(float) ? T(1e17) : T(1e150);

// A packet prepared for box tests.
template <typename T>
struct PacketSlabs {
    using V = typename Simd<T>::type;
    // 1 / direction, clamped to +-max of T: finite, so an axis the ray does not
    // move along gives 0 or +-infinity for its slab, never NaN (0 * infinity).
    V ix, iy, iz;
    V reach;  // |o|_1
    // o + margin and o - margin per axis, the margin kBvhSlack * (|o|_1 + the
    // tree's reach): a box's low side, less the margin, minus o is its low
    // side minus o + margin, one subtraction fewer a side.
    V originPlus[3], originMinus[3];
};

// The sum over axes of the largest |coordinate| of the root's box: at least
// that of any box below it, as each lies inside its parent's.
template <typename T>
inline T treeReach(const SphereBvh<T>& bvh) {
    if (bvh.nodes.empty()) return T(0);
    T reach = 0;
    for (int i = 0; i < 3; ++i) {
        const T l = std::fabs(bvh.nodes[0].lo[i]), h = std::fabs(bvh.nodes[0].hi[i]);
        reach += l > h ? l : h;
    }
    return reach;
}

template <typename T>
inline typename Simd<T>::type clampedInverse(const typename Simd<T>::type& d) {
    using V = typename Simd<T>::type;
    constexpr T kMax = std::numeric_limits<T>::max();
    const V inv = T(1) / d;
    return inv > kMax ? V{} + kMax : (inv < -kMax ? V{} - kMax : inv);
}

template <typename T>
inline typename Simd<T>::type laneAbs(const typename Simd<T>::type& v) {
    return v < T(0) ? -v : v;
}

template <typename T>
inline PacketSlabs<T> packetSlabs(const RayPacket<T>& r, T reachOfTree) {
    PacketSlabs<T> s;
    s.ix = clampedInverse<T>(r.dx);
    s.iy = clampedInverse<T>(r.dy);
    s.iz = clampedInverse<T>(r.dz);
    s.reach = laneAbs<T>(r.ox) + laneAbs<T>(r.oy) + laneAbs<T>(r.oz);
    const typename Simd<T>::type margin = kBvhSlack<T> * (s.reach + reachOfTree);
    const typename Simd<T>::type origin[3] = {r.ox, r.oy, r.oz};
    for (int i = 0; i < 3; ++i) {
        s.originPlus[i] = origin[i] + margin;
        s.originMinus[i] = origin[i] - margin;
    }
    return s;
}

// The lanes of `lanes` whose ray meets the widened box [lo, hi] at some t in
// [0, limit], and each lane's entry distance. A NaN anywhere keeps the lane
// (no comparison is true).
template <typename T>
inline unsigned slabLanes(const float (&lo)[3], const float (&hi)[3], const PacketSlabs<T>& s,
                          const typename Simd<T>::type& limit, unsigned lanes,
                          typename Simd<T>::type& entry) {
    using V = typename Simd<T>::type;
    const V ax = (lo[0] - s.originPlus[0]) * s.ix, bx = (hi[0] - s.originMinus[0]) * s.ix;
    const V ay = (lo[1] - s.originPlus[1]) * s.iy, by = (hi[1] - s.originMinus[1]) * s.iy;
    const V az = (lo[2] - s.originPlus[2]) * s.iz, bz = (hi[2] - s.originMinus[2]) * s.iz;
    const V nx = ax < bx ? ax : bx, fx = ax < bx ? bx : ax;
    const V ny = ay < by ? ay : by, fy = ay < by ? by : ay;
    const V nz = az < bz ? az : bz, fz = az < bz ? bz : az;
    const V nxy = nx > ny ? nx : ny, fxy = fx < fy ? fx : fy;
    entry = nxy > nz ? nxy : nz;
    const V exit = fxy < fz ? fxy : fz;
    const auto miss = (entry > exit) | (exit < T(0)) | (entry > limit);
    return lanes & ~laneBits(miss);
}

// slabLanes() for a node's box.
template <typename T>
inline unsigned boxLanes(const BvhNode& node, const PacketSlabs<T>& s,
                         const typename Simd<T>::type& limit, unsigned lanes,
                         typename Simd<T>::type& entry) {
    return slabLanes(node.lo, node.hi, s, limit, lanes, entry);
}

// A node some lanes are yet to visit, with their entry distances into its box.
template <typename T>
struct BvhVisit {
    typename Simd<T>::type entry;
    unsigned lanes;
    int node;
};

// Visits the leaves whose boxes the lanes' rays meet within [0, limit],
// building a lazy tree's subtrees as the lanes enter them (from `spheres`).
// leaf(node, lanes) returns a mask of the lanes still looking; `limit` may
// shrink meanwhile. inner() is called at each inner node entered (for
// benchmarks/bench_node_width.cpp's counts; nothing in a render).
//
// Both children's boxes are tested when their parent is entered (they lie
// side by side in memory), and a child no lane meets is never stacked. The
// nearer child, by the entry distance of the packet's lowest lane, is visited
// first; the farther one waits with its lanes' entry distances, and those
// lanes whose nearest hit has come closer meanwhile are dropped when it is
// taken up. A lane passes exactly when boxLanes() at that moment would pass it.
template <typename T, typename Leaf, typename Inner = void (*)()>
inline void traverseBvh(
    const SphereSet<T>& spheres, const SphereBvh<T>& bvh, const PacketSlabs<T>& slabs,
    const typename Simd<T>::type& limit, unsigned lanes, Leaf&& leaf, Inner&& inner = [] {}) {
    using V = typename Simd<T>::type;
    BvhVisit<T> stack[kMaxBvhDepth + 1];  // a path's far children: at most its depth
    int top = 0;
    V entry;
    unsigned in = boxLanes(bvh.nodes[0], slabs, limit, lanes, entry);
    int node = 0;
    for (;;) {
        const BvhNode& n = bvh.nodes[node];
        if (in && n.count > 0) {
            lanes &= leaf(n, in);
            if (!lanes) return;
            in = 0;
        }
        if (in && n.count == kLazyNode) {
            node = lazyJobRoot(bvh, n.first, spheres);  // a root with the same box
            continue;
        }
        if (in) {
            inner();
            V entries[2];
            const unsigned inChild[2] = {
                boxLanes(bvh.nodes[n.first], slabs, limit, in, entries[0]),
                boxLanes(bvh.nodes[n.first + 1], slabs, limit, in, entries[1])};
            const int lead = __builtin_ctz(in);
            const auto key = [&](int c) {
                return (inChild[c] >> lead) & 1u ? entries[c][lead]
                                                 : std::numeric_limits<T>::infinity();
            };
            const int near = inChild[0] == 0 || (inChild[1] != 0 && key(1) < key(0)) ? 1 : 0;
            const int far = 1 - near;
            if (inChild[far]) stack[top++] = {entries[far], inChild[far], n.first + far};
            in = inChild[near];
            node = n.first + near;
            if (in) continue;
        }
        // Take up a waiting node, for its lanes still looking and not yet
        // nearer to a hit than to its box.
        do {
            if (top == 0) return;
            const BvhVisit<T>& v = stack[--top];
            in = v.lanes & lanes & ~laneBits(v.entry > limit);
            node = v.node;
        } while (!in);
    }
}

// Lanes of `lanes` whose ray goes into sphere k (its own).
template <typename T>
inline unsigned lanesInto(const RayPacket<T>& r, int k, unsigned lanes) {
    return laneBits((r.originSphere == T(k)) & r.intoOrigin) & lanes;
}

// The sphere's candidate for the nearest hit of each of `lanes`, by
// packetClosestHits()'s rules; ties go to the lower index, so the outcome does
// not depend on the order spheres come in.
template <typename T>
inline void closestUpdate(const SphereSet<T>& spheres, const LeafSphere<T>& sphere,
                          const RayPacket<T>& r, unsigned lanes, typename Simd<T>::type& tBest,
                          typename Simd<T>::type& kBest) {
    using V = typename Simd<T>::type;
    const int k = sphere.index;
    const PacketRoots<T> roots = intersectPacket(spheres, sphere, r, lanes);
    const auto inward = roots.self & r.intoOrigin & maskFromBits<T>(lanes);
    if (!roots.valid && !laneBits(inward)) return;
    const auto exits = roots.hit & (roots.tFar > T(0));
    const V tInward = exits ? roots.tFar : V{} + std::numeric_limits<T>::min();
    const V t = inward ? tInward : (roots.tNear > T(0) ? roots.tNear : roots.tFar);
    const V kk = V{} + T(k);
    const auto take =
        (roots.hit | inward) & (t > T(0)) & ((t < tBest) | ((t == tBest) & (kk < kBest)));
    tBest = take ? t : tBest;
    kBest = take ? kk : kBest;
}

// The start of bvhClosestHits(): tBest and kBest set, the rays' own spheres
// and the spheres kept out of the tree tested. False when nothing is left to
// do: some origin lies beyond the tree's reach (then every sphere has been
// tested, by brute force), or the tree is empty.
template <typename T>
inline bool bvhClosestStart(const SphereSet<T>& spheres, const SphereBvh<T>& bvh,
                            const RayPacket<T>& r, const PacketSlabs<T>& slabs,
                            typename Simd<T>::type& tBest, typename Simd<T>::type& kBest) {
    using V = typename Simd<T>::type;
    if ((laneBits(slabs.reach < kBvhOriginReach<T>) & r.active) != r.active) {
        packetClosestHits(spheres, r, tBest, kBest);
        return false;
    }
    tBest = V{} + std::numeric_limits<T>::infinity();
    kBest = V{} - T(1);
    // A ray going into its own sphere meets it even where rounding says its
    // line misses (the exit at the origin): that sphere first, whatever its box.
    unsigned into = laneBits(r.intoOrigin & maskFromBits<T>(r.active));
    while (into) {
        const int k = static_cast<int>(r.originSphere[__builtin_ctz(into)]);
        const unsigned lanes = lanesInto(r, k, into);
        closestUpdate(spheres, spheres.leafSphere(k), r, lanes, tBest, kBest);
        into &= ~lanes;
    }
    // The huge spheres next: a floor's hit shortens every ray before the tree.
    for (const std::int32_t k : bvh.direct)
        closestUpdate(spheres, spheres.leafSphere(k), r, r.active, tBest, kBest);
    return !bvh.nodes.empty();
}

// packetClosestHits() through the tree. Kept out of line, as is
// bvhTransmittance(): inlined into the kernel's packet loop beside the
// brute-force path, it cost the seed's render (brute force) 0.5% more
// instructions; out of line, the 100k field's render costs 2% more
// instructions and 15% fewer L1 misses (callgrind, docs/design/acceleration.md).
template <typename T>
__attribute__((noinline)) void bvhClosestHits(const SphereSet<T>& spheres, const SphereBvh<T>& bvh,
                                              const RayPacket<T>& r, typename Simd<T>::type& tBest,
                                              typename Simd<T>::type& kBest) {
    const PacketSlabs<T> slabs = packetSlabs(r, treeReach(bvh));
    if (!bvhClosestStart(spheres, bvh, r, slabs, tBest, kBest)) return;
    // Testing a ray's own sphere again changes nothing: its (t, k) is already kept.
    auto leaf = [&](const BvhNode& node, unsigned lanes) {
        for (int i = node.first; i < node.first + node.count; ++i)
            closestUpdate(spheres, bvh.leafSpheres[i], r, lanes, tBest, kBest);
        return ~0u;
    };
    traverseBvh(spheres, bvh, slabs, tBest, r.active, leaf);
}

// The spheres each lane's shadow ray crosses, to be multiplied in index order.
template <typename T>
struct Occluders {
    static constexpr int kCapacity = 32;  // more, and the lane is redone by brute force
    int count[RayPacket<T>::kWidth] = {};
    std::int32_t sphere[RayPacket<T>::kWidth][kCapacity];
    unsigned opaque = 0;    // lanes that cross an opaque sphere: S = 0
    unsigned overflow = 0;  // lanes that crossed more than kCapacity transparent spheres

    void add(unsigned lanes, int k, T transparency) {
        if (transparency == T(0)) {
            opaque |= lanes;
            return;
        }
        if (transparency == T(1)) return;  // s * 1 == s exactly
        for (; lanes; lanes &= lanes - 1) {
            const int l = __builtin_ctz(lanes);
            if (count[l] < kCapacity)
                sphere[l][count[l]++] = k;
            else
                overflow |= 1u << l;
        }
    }
};

// The sphere's part in each lane's transmittance, by packetTransmittance()'s rules.
template <typename T>
inline void shadowUpdate(const SphereSet<T>& spheres, const std::vector<T>& transparency,
                         const LeafSphere<T>& sphere, const RayPacket<T>& r,
                         const typename Simd<T>::type& distance, unsigned lanes,
                         Occluders<T>& out) {
    const int k = sphere.index;
    const PacketRoots<T> roots = intersectPacket(spheres, sphere, r, lanes);
    const auto inward = roots.self & r.intoOrigin & maskFromBits<T>(lanes);
    if (!roots.valid && !laneBits(inward)) return;
    const auto exits = roots.hit & (roots.tFar > T(0));
    const auto crossesOwn = exits ? roots.tFar < distance : distance > T(0);
    const auto crossesOther = ((roots.tNear > T(0)) & (roots.tNear < distance)) |
                              ((roots.tFar > T(0)) & (roots.tFar < distance));
    const auto take = inward ? crossesOwn : crossesOther & roots.hit;
    if (const unsigned bits = laneBits(take) & lanes) out.add(bits, k, transparency[k]);
}

// Insertion sort of a lane's few occluders. Not std::sort: its helpers would be
// instantiated outside this instruction set's namespace (isa_namespace.h).
inline void sortIndices(std::int32_t* first, std::int32_t* last) {
    for (std::int32_t* i = first + (first != last); i < last; ++i) {
        const std::int32_t v = *i;
        std::int32_t* j = i;
        for (; j > first && j[-1] > v; --j) *j = j[-1];
        *j = v;
    }
}

// packetTransmittance() through the tree.
template <typename T>
__attribute__((noinline)) typename Simd<T>::type bvhTransmittance(
    const SphereSet<T>& spheres, const std::vector<T>& transparency, const SphereBvh<T>& bvh,
    const RayPacket<T>& r, const typename Simd<T>::type& distance, unsigned lanes) {
    using V = typename Simd<T>::type;
    const PacketSlabs<T> slabs = packetSlabs(r, treeReach(bvh));
    if ((laneBits(slabs.reach < kBvhOriginReach<T>) & lanes) != lanes)
        return packetTransmittance(spheres, transparency, r, distance, lanes);
    Occluders<T> found;
    unsigned into = laneBits(r.intoOrigin & maskFromBits<T>(lanes));
    const unsigned goingIn = into;
    while (into) {
        const int k = static_cast<int>(r.originSphere[__builtin_ctz(into)]);
        const unsigned own = lanesInto(r, k, into);
        shadowUpdate(spheres, transparency, spheres.leafSphere(k), r, distance, own, found);
        into &= ~own;
    }
    for (const std::int32_t k : bvh.direct)
        if (const unsigned open = lanes & ~found.opaque)
            shadowUpdate(spheres, transparency, spheres.leafSphere(k), r, distance,
                         goingIn ? open & ~lanesInto(r, k, goingIn) : open, found);
    auto leaf = [&](const BvhNode& node, unsigned in) {
        for (int i = node.first; i < node.first + node.count && in; ++i) {
            const LeafSphere<T>& sphere = bvh.leafSpheres[i];
            // Its own sphere was counted above; once is all.
            const unsigned test = goingIn ? in & ~lanesInto(r, sphere.index, goingIn) : in;
            if (test) shadowUpdate(spheres, transparency, sphere, r, distance, test, found);
            in &= ~found.opaque;
        }
        return ~found.opaque;
    };
    if (!bvh.nodes.empty() && (lanes & ~found.opaque)) {
        traverseBvh(spheres, bvh, slabs, distance, lanes & ~found.opaque, leaf);
    }
    V s = V{} + T(1);
    for (unsigned open = lanes & ~found.opaque & ~found.overflow; open; open &= open - 1) {
        const int l = __builtin_ctz(open);
        std::int32_t* first = found.sphere[l];
        std::int32_t* last = first + found.count[l];
        sortIndices(first, last);
        T product = T(1);
        for (const std::int32_t* k = first; k != last; ++k) product = product * transparency[*k];
        s[l] = product;
    }
    for (unsigned bits = found.opaque & lanes; bits; bits &= bits - 1)
        s[__builtin_ctz(bits)] = T(0);
    if (const unsigned redo = found.overflow & ~found.opaque & lanes) {
        const V brute = packetTransmittance(spheres, transparency, r, distance, redo);
        for (unsigned bits = redo; bits; bits &= bits - 1) {
            const int l = __builtin_ctz(bits);
            s[l] = brute[l];
        }
    }
    return s;
}

// The nearest hits and the transmittance of a packet, through the tree when
// the scene has one (bvh non-null), else by testing every sphere.
template <typename T>
inline void sceneClosestHits(const SphereSet<T>& spheres, const SphereBvh<T>* bvh,
                             const RayPacket<T>& r, typename Simd<T>::type& tBest,
                             typename Simd<T>::type& kBest) {
    if (bvh)
        bvhClosestHits(spheres, *bvh, r, tBest, kBest);
    else
        packetClosestHits(spheres, r, tBest, kBest);
}

template <typename T>
inline typename Simd<T>::type sceneTransmittance(const SphereSet<T>& spheres,
                                                 const std::vector<T>& transparency,
                                                 const SphereBvh<T>* bvh, const RayPacket<T>& r,
                                                 const typename Simd<T>::type& distance,
                                                 unsigned lanes,
                                                 const ShadowCone<T>* cones = nullptr) {
    return bvh ? bvhTransmittance(spheres, transparency, *bvh, r, distance, lanes)
               : packetTransmittance(spheres, transparency, r, distance, lanes, cones);
}

}  // namespace WHITTED_ISA_NAMESPACE
}  // namespace whitted
