// Box tests of the sphere BVH's traversal (bvh_traverse.h): a packet's rays
// against one node's box, and one ray against both children of a node. Both
// do the same arithmetic in the same order, so a lane passes a box alone
// exactly when it would pass it in its packet.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#include "tracer/bvh.h"
#include "tracer/isa_namespace.h"
#include "tracer/ray_packet.h"
#include "tracer/simd.h"

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
// Double packets test boxes in float where the target's vectors hold 32 bytes
// or more (Walk below): on these cores a 64-byte operation takes the time of
// two 32-byte ones, so eight lanes' box tests in float cost half what they do
// in double, and the boxes are float already. The rays are rounded to float
// for it: o and d each by eps_f / 2 of themselves, which moves the point at t
// by at most eps_f / 2 (|o| + t |d|) an axis; t |d| <= |o| + |p| for a point p
// in the tree's root box, so by eps_f (|o|_1 + reach): a 64th of the float
// margin, used for these tests. A double root's own error is far smaller still
// (DoubleRaysWalkedInFloat_MeetTheBoxesOfTheirHits). The entry distances, in
// float, are compared with double limits exactly (a float converts exactly).
//
// The argument needs squares of coordinates to be finite in T, and the
// margin to be finite in the walk's arithmetic: spheres beyond kTreeReach
// (bvh_boxes.h) stay out of the tree, and packets whose origins lie beyond
// kBvhOriginReach take the brute-force loop.
template <typename T>
struct Walk {
    using scalar = T;
    using type = typename Simd<T>::type;
};
#if defined(__AVX__)
// With SSE alone, a vector of two floats would be split lane by lane.
template <>
struct Walk<double> {
    using scalar = float;
    typedef float type __attribute__((vector_size(kSimdBytes / 2)));
};
#endif

template <typename T>
inline constexpr T kBvhSlack = T(64) * std::numeric_limits<T>::epsilon();
// Squares of 1e17 are finite in float and of 1e150 in double; the float walk
// of double packets needs its sums of 1e37 finite.
template <typename T>
inline constexpr
    typename Walk<T>::scalar kBvhOriginReach(sizeof(T) == sizeof(float) ? 1e17
                                             : sizeof(typename Walk<T>::scalar) == sizeof(float)
                                                 ? 1e37
                                                 : 1e150);

// v's lanes as the vector type To: v itself if it is one; double to float to
// nearest (a ray into the walk's arithmetic), float to double exactly (an
// entry distance, to compare with a double limit).
template <typename To, typename From>
inline To lanesAs(const From& v) {
    if constexpr (std::is_same_v<To, From>)
        return v;
    else
        return __builtin_convertvector(v, To);
}

// A packet prepared for box tests, in the walk's arithmetic.
template <typename T>
struct PacketSlabs {
    using W = typename Walk<T>::scalar;
    using V = typename Walk<T>::type;
    // 1 / direction, clamped to +-max of W: finite, so an axis the ray does not
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

template <typename V>
inline V clampedInverse(const V& d) {
    using S = std::remove_cvref_t<decltype(d[0])>;
    constexpr S kMax = std::numeric_limits<S>::max();
    const V inv = S(1) / d;
    return inv > kMax ? V{} + kMax : (inv < -kMax ? V{} - kMax : inv);
}

template <typename V>
inline V laneAbs(const V& v) {
    using S = std::remove_cvref_t<decltype(v[0])>;
    return v < S(0) ? -v : v;
}

template <typename T>
inline PacketSlabs<T> packetSlabs(const RayPacket<T>& r, T reachOfTree) {
    using W = typename Walk<T>::scalar;
    using V = typename Walk<T>::type;
    PacketSlabs<T> s;
    const V origin[3] = {lanesAs<V>(r.ox), lanesAs<V>(r.oy), lanesAs<V>(r.oz)};
    s.ix = clampedInverse(lanesAs<V>(r.dx));
    s.iy = clampedInverse(lanesAs<V>(r.dy));
    s.iz = clampedInverse(lanesAs<V>(r.dz));
    s.reach = laneAbs(origin[0]) + laneAbs(origin[1]) + laneAbs(origin[2]);
    const V margin = kBvhSlack<W> * (s.reach + W(reachOfTree));
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
                          typename Walk<T>::type& entry) {
    using V = typename Walk<T>::type;
    const V ax = (lo[0] - s.originPlus[0]) * s.ix, bx = (hi[0] - s.originMinus[0]) * s.ix;
    const V ay = (lo[1] - s.originPlus[1]) * s.iy, by = (hi[1] - s.originMinus[1]) * s.iy;
    const V az = (lo[2] - s.originPlus[2]) * s.iz, bz = (hi[2] - s.originMinus[2]) * s.iz;
    const V nx = ax < bx ? ax : bx, fx = ax < bx ? bx : ax;
    const V ny = ay < by ? ay : by, fy = ay < by ? by : ay;
    const V nz = az < bz ? az : bz, fz = az < bz ? bz : az;
    const V nxy = nx > ny ? nx : ny, fxy = fx < fy ? fx : fy;
    entry = nxy > nz ? nxy : nz;
    const V exit = fxy < fz ? fxy : fz;
    using W = typename Walk<T>::scalar;
    if constexpr (std::is_same_v<W, T>)
        return lanes & ~laneBits((entry > exit) | (exit < W(0)) | (entry > limit));
    else
        return lanes & ~laneBits((entry > exit) | (exit < W(0))) &
               ~laneBits(lanesAs<typename Simd<T>::type>(entry) > limit);
}

// slabLanes() for a node's box.
template <typename T>
inline unsigned boxLanes(const BvhNode& node, const PacketSlabs<T>& s,
                         const typename Simd<T>::type& limit, unsigned lanes,
                         typename Walk<T>::type& entry) {
    return slabLanes(node.lo, node.hi, s, limit, lanes, entry);
}

// One lane's ray against both children of a node at once: the two 32-byte
// nodes lie side by side (bvh.h), so one 64-byte load holds both boxes as
// [lo (3), hi (3), first, count] twice, and the ray's values are laid out the
// same way. Every slab of both boxes is then one subtraction and one
// multiplication, in place of a 16-lane box test per child for the one lane
// still looking. The ternaries are slabLanes()'s, lane for lane, NaN included.
template <typename T>
struct PairSimd;
template <>
struct PairSimd<float> {
    typedef float type __attribute__((vector_size(64)));
    typedef std::int32_t index __attribute__((vector_size(64)));
};
template <>
struct PairSimd<double> {
    typedef double type __attribute__((vector_size(128)));
    typedef std::int64_t index __attribute__((vector_size(128)));
};

template <typename T>
struct LaneSlabs {
    using Pair = typename PairSimd<typename Walk<T>::scalar>::type;
    Pair origin;   // [o + margin (3), o - margin (3), 0, 0], twice
    Pair inverse;  // [1/d (3), 1/d (3), 0, 0], twice
};

template <typename T>
inline LaneSlabs<T> laneSlabs(const PacketSlabs<T>& s, int lane) {
    const typename Walk<T>::scalar inverse[3] = {s.ix[lane], s.iy[lane], s.iz[lane]};
    LaneSlabs<T> r{};
    for (int child = 0; child < 2; ++child) {
        for (int i = 0; i < 3; ++i) {
            r.origin[8 * child + i] = s.originPlus[i][lane];
            r.origin[8 * child + 3 + i] = s.originMinus[i][lane];
            r.inverse[8 * child + i] = inverse[i];
            r.inverse[8 * child + 3 + i] = inverse[i];
        }
    }
    return r;
}

// Which of the two sibling nodes at `children` the ray meets within
// [0, limit] (bit c: children[c]), and its entry distance into each.
template <typename T>
inline unsigned childrenMet(const BvhNode* children, const LaneSlabs<T>& s, T limit,
                            typename Walk<T>::scalar (&entry)[2]) {
    using W = typename Walk<T>::scalar;
    using Pair = typename PairSimd<W>::type;
    using Index = typename PairSimd<W>::index;
    typename PairSimd<float>::type boxes;
    std::memcpy(&boxes, children, sizeof boxes);
    // The two ints read as floats may be NaN or subnormal: zeroed, they cost nothing.
    const typename PairSimd<float>::index keep = {-1, -1, -1, -1, -1, -1, 0, 0,
                                                  -1, -1, -1, -1, -1, -1, 0, 0};
    boxes = reinterpret_cast<typename PairSimd<float>::type>(
        reinterpret_cast<typename PairSimd<float>::index>(boxes) & keep);
    Pair t;
    if constexpr (sizeof(W) == sizeof(float))
        t = (boxes - s.origin) * s.inverse;
    else
        t = (__builtin_convertvector(boxes, Pair) - s.origin) * s.inverse;
    // Per axis: a the low side's distance, b the high side's (slabLanes()).
    const Pair other =
        __builtin_shuffle(t, Index{3, 4, 5, 0, 1, 2, 6, 7, 11, 12, 13, 8, 9, 10, 14, 15});
    const Pair nearSide = t < other ? t : other, farSide = t < other ? other : t;
    const Index toY = {1, 1, 1, 1, 1, 1, 1, 1, 9, 9, 9, 9, 9, 9, 9, 9};
    const Index toZ = {2, 2, 2, 2, 2, 2, 2, 2, 10, 10, 10, 10, 10, 10, 10, 10};
    const Pair ny = __builtin_shuffle(nearSide, toY), nz = __builtin_shuffle(nearSide, toZ);
    const Pair fy = __builtin_shuffle(farSide, toY), fz = __builtin_shuffle(farSide, toZ);
    const Pair nxy = nearSide > ny ? nearSide : ny, fxy = farSide < fy ? farSide : fy;
    const Pair in = nxy > nz ? nxy : nz, out = fxy < fz ? fxy : fz;
    unsigned met = 0;
    for (int c = 0; c < 2; ++c) {
        entry[c] = in[8 * c];
        const W exit = out[8 * c];
        if (!((entry[c] > exit) | (exit < W(0)) | (entry[c] > limit))) met |= 1u << c;
    }
    return met;
}

}  // namespace WHITTED_ISA_NAMESPACE
}  // namespace whitted
