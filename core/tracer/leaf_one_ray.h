// One ray against every sphere of a leaf at once, SIMD over the spheres: where
// a packet has a single lane left in a leaf (most leaf visits in a cloud of
// balls, docs/design/acceleration.md), the packet test would cost a whole
// vector operation and a branch per sphere for that one lane.
//
// Each sphere lane does intersectPacket()'s and closestUpdate()'s operations in
// their order, so the ray finds the same (t, sphere) as in its packet, to the
// bit; the nearest of the leaf's candidates then goes through closestUpdate()'s
// rule once, which is the same as through it sphere by sphere, since that rule
// keeps the least (t, index) whatever the order.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "tracer/isa_namespace.h"
#include "tracer/ray_packet.h"
#include "tracer/simd.h"
#include "tracer/sphere_set.h"

namespace whitted {

inline namespace WHITTED_ISA_NAMESPACE {

// Up to a vector's worth of a leaf's spheres, one to a lane.
template <typename T>
struct SphereLanes {
    using V = typename Simd<T>::type;
    V cx, cy, cz, rrHi, cameraC, index;
    int count;
};

template <typename T>
inline SphereLanes<T> sphereLanes(const LeafSphere<T>* leaf, int count) {
    constexpr int kWidth = RayPacket<T>::kWidth;
    alignas(kSimdBytes) T field[6][kWidth] = {};
    for (int i = 0; i < count; ++i) {
        field[0][i] = leaf[i].centre.x;
        field[1][i] = leaf[i].centre.y;
        field[2][i] = leaf[i].centre.z;
        field[3][i] = leaf[i].rrHi;
        field[4][i] = leaf[i].cameraC;
        field[5][i] = T(leaf[i].index);
    }
    SphereLanes<T> s;
    typename Simd<T>::type* out[6] = {&s.cx, &s.cy, &s.cz, &s.rrHi, &s.cameraC, &s.index};
    for (int f = 0; f < 6; ++f) __builtin_memcpy(out[f], field[f], sizeof(s.cx));
    s.count = count;
    return s;
}

// The spheres indices[0, count) as sphereLanes() lays them out, for rays that
// do not come from the camera (cameraC is left 0).
template <typename T>
inline SphereLanes<T> sphereLanesOf(const SphereSet<T>& spheres, const std::int32_t* indices,
                                    int count) {
    constexpr int kWidth = RayPacket<T>::kWidth;
    alignas(kSimdBytes) T field[5][kWidth] = {};
    for (int i = 0; i < count; ++i) {
        const std::int32_t k = indices[i];
        field[0][i] = spheres.centre[k].x;
        field[1][i] = spheres.centre[k].y;
        field[2][i] = spheres.centre[k].z;
        field[3][i] = spheres.rrHi[k];
        field[4][i] = T(k);
    }
    SphereLanes<T> s;
    typename Simd<T>::type* out[5] = {&s.cx, &s.cy, &s.cz, &s.rrHi, &s.index};
    for (int f = 0; f < 5; ++f) __builtin_memcpy(out[f], field[f], sizeof(s.cx));
    s.cameraC = typename Simd<T>::type{};
    s.count = count;
    return s;
}

// intersectPacket() of lane `lane` of `r` against every sphere of `s`.
template <typename T>
struct OneRayRoots {
    typename Simd<T>::type tNear, tFar;
    unsigned hit;     // spheres whose surface the ray's line meets (PacketRoots::hit)
    unsigned inward;  // the ray's own sphere, if the ray goes into it
};

template <typename T>
inline OneRayRoots<T> oneRayRoots(const SphereSet<T>& spheres, const SphereLanes<T>& s,
                                  const RayPacket<T>& r, int lane) {
    using V = typename Simd<T>::type;
    const unsigned live = s.count >= RayPacket<T>::kWidth ? ~0u : (1u << s.count) - 1;
    const bool into = r.intoOrigin[lane] != 0;
    const unsigned self = laneBits(s.index == r.originSphere[lane]) & live;
    OneRayRoots<T> out;
    out.inward = into ? self : 0u;
    // Leaving its own sphere outwards, a ray cannot meet it again (convex).
    const unsigned tested = into ? live : live & ~self;
    const V dx = V{} + r.dx[lane], dy = V{} + r.dy[lane], dz = V{} + r.dz[lane];
    const V fx = r.ox[lane] - s.cx, fy = r.oy[lane] - s.cy, fz = r.oz[lane] - s.cz;
    const V b = fx * dx + fy * dy + fz * dz;
    const V ff = fx * fx + fy * fy + fz * fz;
    V c = r.fromCamera ? s.cameraC : ff - s.rrHi;
    const auto away = (b > T(0)) & (c > ff * (T(16) * std::numeric_limits<T>::epsilon()));
    const auto nearSurface = (c < ff * T(0.0625)) & (c > -(ff * T(0.0625)));
    if (!r.fromCamera) {
        for (unsigned fix = laneBits(nearSurface & ~away) & tested; fix; fix &= fix - 1) {
            const int i = __builtin_ctz(fix);
            const int k = static_cast<int>(s.index[i]);
            c[i] = accurateOffsetSquared(r.origin(lane), spheres.centre[k], spheres.centreLo[k],
                                         s.rrHi[i], spheres.rrLo[k]);
        }
    }
    const V px = fx - b * dx, py = fy - b * dy, pz = fz - b * dz;
    const V discNear = b * b - c;
    const V discFar = s.rrHi - (px * px + py * py + pz * pz);
    const V disc = nearSurface ? discNear : discFar;
    const auto hitLine = ~away & (disc >= T(0));
    out.hit = laneBits(hitLine) & tested;
    if (!out.hit) {
        out.tNear = out.tFar = V{};  // as intersectPacket() leaves them
        return out;
    }
    const OrderedRoots<T> roots = orderedRoots<T>(b, c, disc, hitLine);
    out.tNear = roots.tNear;
    out.tFar = roots.tFar;
    return out;
}

// closestUpdate() of lane `lane` of `r` for every sphere of `s`.
template <typename T>
inline void closestUpdateOneRay(const SphereSet<T>& spheres, const SphereLanes<T>& s,
                                const RayPacket<T>& r, int lane, T& tBest, T& kBest) {
    using V = typename Simd<T>::type;
    const OneRayRoots<T> roots = oneRayRoots(spheres, s, r, lane);
    if (!roots.hit && !roots.inward) return;
    const auto exits = maskFromBits<T>(roots.hit) & (roots.tFar > T(0));
    const V tInward = exits ? roots.tFar : V{} + std::numeric_limits<T>::min();
    const V t =
        maskFromBits<T>(roots.inward) ? tInward : (roots.tNear > T(0) ? roots.tNear : roots.tFar);
    // The least (t, index) of the candidates, then closestUpdate()'s rule.
    unsigned candidates = laneBits(t > T(0)) & (roots.hit | roots.inward);
    for (; candidates; candidates &= candidates - 1) {
        const int i = __builtin_ctz(candidates);
        if (t[i] < tBest || (t[i] == tBest && s.index[i] < kBest)) {
            tBest = t[i];
            kBest = s.index[i];
        }
    }
}

// The spheres of `s` lane `lane`'s shadow ray crosses before `distance`, by
// shadowUpdate()'s rules, added to `out` (in any order: bvhTransmittance()
// sorts them before it multiplies their transparencies). Its own sphere, if
// it goes into it, is left out: bvhTransmittance() counts that one first.
template <typename T, typename Occluders>
inline void shadowUpdateOneRay(const SphereSet<T>& spheres, const std::vector<T>& transparency,
                               const SphereLanes<T>& s, const RayPacket<T>& r, int lane, T distance,
                               Occluders& out) {
    const OneRayRoots<T> roots = oneRayRoots(spheres, s, r, lane);
    const unsigned hit = roots.hit & ~roots.inward;
    if (!hit) return;
    const auto crosses = ((roots.tNear > T(0)) & (roots.tNear < distance)) |
                         ((roots.tFar > T(0)) & (roots.tFar < distance));
    for (unsigned bits = laneBits(crosses) & hit; bits; bits &= bits - 1) {
        const int k = static_cast<int>(s.index[__builtin_ctz(bits)]);
        out.add(1u << lane, k, transparency[k]);
    }
}

}  // namespace WHITTED_ISA_NAMESPACE
}  // namespace whitted
