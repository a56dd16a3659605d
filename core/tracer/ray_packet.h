// Packets of rays intersected with the scene several at a time.
//
// Several rays (a SIMD vector's worth) go against one sphere after another: shadow rays
// towards one light, the reflected rays of neighbouring pixels and camera rays
// come in such groups. Every lane performs exactly the operations of
// intersectSphere() in the same order, so a ray finds the same hit alone or in
// a packet, whatever its neighbours (tests/core/test_ray_packet.cpp).
#pragma once

#include <cstdint>
#include <limits>
#include <type_traits>

#include "tracer/isa_namespace.h"
#include "tracer/screen_boxes.h"
#include "tracer/shadow_cones.h"
#include "tracer/simd.h"
#include "tracer/simd_vec3.h"
#include "tracer/sphere_intersect.h"
#include "tracer/sphere_set.h"

namespace whitted {

inline namespace WHITTED_ISA_NAMESPACE {

template <typename T>
struct RayPacket {
    static constexpr int kWidth = kSimdBytes / sizeof(T);
    using V = typename Simd<T>::type;
    using Mask = decltype(V{} < V{});
    using MaskLane = std::remove_reference_t<decltype(Mask{}[0])>;  // int32 or int64

    V ox{}, oy{}, oz{};  // origins
    V dx{}, dy{}, dz{};  // unit directions
    // The sphere each ray leaves (-1: none) as T, so lanes compare in one
    // instruction; exact for any sphere count a scene file can hold in memory.
    V originSphere = V{} - T(1);
    Mask intoOrigin{};        // the ray goes into originSphere
    bool fromCamera = false;  // every origin is the camera position
    unsigned active = 0;      // bit l: lane l holds a ray
    // Which of the first kScreenBoxedSpheres spheres brute force tests (bit
    // k: sphere k); every sphere after those is tested.
    std::uint32_t spheres = ~0u;

    void set(int l, const Vec<T>& o, const Vec<T>& d, int sphere, bool into) {
        ox[l] = o.x;
        oy[l] = o.y;
        oz[l] = o.z;
        dx[l] = d.x;
        dy[l] = d.y;
        dz[l] = d.z;
        originSphere[l] = T(sphere);
        intoOrigin[l] = into ? MaskLane(-1) : MaskLane(0);
        active |= 1u << l;
    }
    // Every lane at once; `lanes` says which of them hold rays. Built whole
    // rather than assigned to a default packet: zeroing a packet first cost a
    // memset call per packet (callgrind, docs/design/acceleration.md).
    static RayPacket of(const Vec3x<T>& o, const Vec3x<T>& d, const V& sphere, const Mask& into,
                        unsigned lanes, bool fromCamera = false) {
        return {o.x, o.y, o.z, d.x, d.y, d.z, sphere, into, fromCamera, lanes};
    }
    Vec<T> origin(int l) const { return {ox[l], oy[l], oz[l]}; }
    Vec<T> dir(int l) const { return {dx[l], dy[l], dz[l]}; }
    Vec3x<T> origins() const { return {ox, oy, oz}; }
    Vec3x<T> dirs() const { return {dx, dy, dz}; }
};

// The mask with lane l set where bit l of `bits` is.
template <typename T>
inline typename RayPacket<T>::Mask maskFromBits(unsigned bits) {
    using Mask = typename RayPacket<T>::Mask;
    Mask laneBit{};
    for (int l = 0; l < RayPacket<T>::kWidth; ++l) laneBit[l] = 1 << l;  // folded at compile time
    return (laneBit & static_cast<typename RayPacket<T>::MaskLane>(bits)) != 0;
}

// Roots of every lane's ray against sphere k. Lanes not set in `lanes`, and the
// ray leaving sphere k outwards, report no hit and cost no exact fix-up.
template <typename T>
struct PacketRoots {
    using V = typename Simd<T>::type;
    V tNear{}, tFar{};
    typename RayPacket<T>::Mask self{};  // lanes whose ray leaves (into) sphere k
    typename RayPacket<T>::Mask hit{};   // lanes whose line meets sphere k
    unsigned valid = 0;                  // the same as bits: bit l for lane l
};

// c of intersectSphere() where the origin is near the sphere's surface, for
// the lanes of `fix`: accurateOffsetSquared() for one lane, else for every lane
// at once, which costs about as much as the scalar function twice
// (callgrind: scalar lane by lane was 3% of a float render).
template <typename T>
inline typename Simd<T>::type exactC(const SphereSet<T>& spheres, const LeafSphere<T>& sphere,
                                     const RayPacket<T>& r, unsigned fix,
                                     typename Simd<T>::type c) {
    const int k = sphere.index;
    if (!(fix & (fix - 1))) {
        const int l = __builtin_ctz(fix);
        c[l] = accurateOffsetSquared(r.origin(l), sphere.centre, spheres.centreLo[k], sphere.rrHi,
                                     spheres.rrLo[k]);
        return c;
    }
    const typename Simd<T>::type all = accurateOffsetSquaredLanes<typename Simd<T>::type, T>(
        {r.ox, r.oy, r.oz}, sphere.centre, spheres.centreLo[k], sphere.rrHi, spheres.rrLo[k]);
    return maskFromBits<T>(fix) ? all : c;
}

// The roots of t^2 + 2bt + c, whose discriminant b^2 - c is `disc` (worked
// out one of two ways), in the lanes of `hit`, by intersectSphere()'s
// formulas, the nearer first. Shared with oneRayRoots() (leaf_one_ray.h),
// which tests one ray against a sphere a lane.
template <typename T>
struct OrderedRoots {
    typename Simd<T>::type tNear, tFar;
};

template <typename T, typename M>
inline OrderedRoots<T> orderedRoots(const typename Simd<T>::type& b,
                                    const typename Simd<T>::type& c,
                                    const typename Simd<T>::type& disc, const M& hit) {
    using V = typename Simd<T>::type;
    const V root = laneSqrt(hit ? disc : V{});
    const V q = -b - (b < T(0) ? -root : root);  // as in intersectSphere()
    const auto zero = q == T(0);
    const V t0 = zero ? V{} : c / (zero ? V{} + T(1) : q);
    const V t1 = zero ? V{} : q;
    const auto ordered = t0 < t1;
    return {ordered ? t0 : t1, ordered ? t1 : t0};
}

// `sphere` is spheres.leafSphere(k), from wherever it was read (the sphere
// tree keeps copies in leaf order): the same values, so the same roots.
template <typename T>
[[gnu::always_inline]] inline PacketRoots<T> intersectPacket(const SphereSet<T>& spheres,
                                                             const LeafSphere<T>& sphere,
                                                             const RayPacket<T>& r,
                                                             unsigned lanes) {
    using V = typename Simd<T>::type;
    const int k = sphere.index;
    const T cx = sphere.centre.x, cy = sphere.centre.y, cz = sphere.centre.z;
    const T rrHi = sphere.rrHi;
    PacketRoots<T> out;
    out.self = r.originSphere == T(k);
    lanes &= ~laneBits(out.self & ~r.intoOrigin);  // convex: leaving it, it cannot be hit again
    out.valid = 0;
    if (!lanes) return out;
    const V fx = r.ox - cx, fy = r.oy - cy, fz = r.oz - cz;
    const V b = fx * r.dx + fy * r.dy + fz * r.dz;
    const V ff = fx * fx + fy * fy + fz * fz;
    V c = r.fromCamera ? V{} + sphere.cameraC : ff - rrHi;
    const auto away = (b > T(0)) & (c > ff * (T(16) * std::numeric_limits<T>::epsilon()));
    const auto nearSurface = (c < ff * T(0.0625)) & (c > -(ff * T(0.0625)));
    if (!r.fromCamera) {
        if (const unsigned fix = laneBits(nearSurface & ~away) & lanes)
            c = exactC(spheres, sphere, r, fix, c);
    }
    const V px = fx - b * r.dx, py = fy - b * r.dy, pz = fz - b * r.dz;
    const V discNear = b * b - c;
    const V discFar = rrHi - (px * px + py * py + pz * pz);
    const V disc = nearSurface ? discNear : discFar;
    const auto hit = ~away & (disc >= T(0));
    out.valid = laneBits(hit) & lanes;
    if (!out.valid) return out;
    out.hit = hit & maskFromBits<T>(lanes);
    const OrderedRoots<T> roots = orderedRoots<T>(b, c, disc, hit);
    out.tNear = roots.tNear;
    out.tFar = roots.tFar;
    return out;
}

template <typename T>
inline PacketRoots<T> intersectPacket(const SphereSet<T>& spheres, int k, const RayPacket<T>& r,
                                      unsigned lanes) {
    return intersectPacket(spheres, spheres.leafSphere(k), r, lanes);
}

// Calls test(k) for each sphere k that packet `r` is tested against by brute
// force, in index order (r.spheres).
template <typename T, typename Test>
inline void forTestedSpheres(const RayPacket<T>& r, int count, Test test) {
    // Not std::min, which would take the constant by reference and so define
    // it in this instruction set's object (check_kernel_symbols.cmake).
    const int boxed = count < kScreenBoxedSpheres ? count : kScreenBoxedSpheres;
    const std::uint32_t all = boxed == 32 ? ~0u : (1u << boxed) - 1;  // no shift by 32
    for (std::uint32_t bits = r.spheres & all; bits; bits &= bits - 1) test(__builtin_ctz(bits));
    for (int k = boxed; k < count; ++k) test(k);
}

// Nearest hit per lane with t in (0, infinity): t, and the sphere index as T
// (-1 for a miss). Ties go to the lower sphere index, as in closestHit().
template <typename T>
inline void packetClosestHits(const SphereSet<T>& spheres, const RayPacket<T>& r,
                              typename Simd<T>::type& tBest, typename Simd<T>::type& kBest) {
    using V = typename Simd<T>::type;
    tBest = V{} + std::numeric_limits<T>::infinity();
    kBest = V{} - T(1);
    // Camera rays and rays reflected off outsides never go into a sphere: they
    // take the plain loop; the exit rule below is for rays going into their own.
    const bool mayGoIn = laneBits(r.intoOrigin & maskFromBits<T>(r.active)) != 0;
    forTestedSpheres(r, spheres.count(), [&](int k) {
        const PacketRoots<T> roots = intersectPacket(spheres, k, r, r.active);
        if (!mayGoIn) {
            if (!roots.valid) return;
            const V t = roots.tNear > T(0) ? roots.tNear : roots.tFar;
            const auto take = roots.hit & (t > T(0)) & (t < tBest);
            tBest = take ? t : tBest;
            kBest = take ? V{} + T(k) : kBest;
            return;
        }
        const auto inward = roots.self & r.intoOrigin & maskFromBits<T>(r.active);
        if (!roots.valid && !laneBits(inward)) return;
        // Going into its own sphere, a ray can only meet the far side, and must
        // meet it: where the origin's rounding error (off the surface by ~eps|p|)
        // makes a grazing line miss or puts the exit behind it, the ray leaves
        // where it starts, the smallest t > 0.
        const auto exits = roots.hit & (roots.tFar > T(0));
        const V tInward = exits ? roots.tFar : V{} + std::numeric_limits<T>::min();
        const V t = inward ? tInward : (roots.tNear > T(0) ? roots.tNear : roots.tFar);
        const auto take = (roots.hit | inward) & (t > T(0)) & (t < tBest);
        tBest = take ? t : tBest;
        kBest = take ? V{} + T(k) : kBest;
    });
}

// S_j per lane: the product of the transparencies of the spheres each shadow
// ray crosses before `distance`, in sphere order (SPEC §3). With `cones`
// (shadow_cones.h, one a sphere), a sphere is tested only for the lanes whose
// direction lies in its cone, and for the rays that leave it.
template <typename T>
inline typename Simd<T>::type packetTransmittance(
    const SphereSet<T>& spheres, const std::vector<T>& transparency, const RayPacket<T>& r,
    const typename Simd<T>::type& distance, unsigned lanes, const ShadowCone<T>* cones = nullptr) {
    using V = typename Simd<T>::type;
    V s = V{} + T(1);
    const bool mayGoIn = laneBits(r.intoOrigin & maskFromBits<T>(lanes)) != 0;
    for (int k = 0; k < spheres.count() && lanes; ++k) {
        unsigned tested = lanes;
        if (cones) {
            const ShadowCone<T>& cone = cones[k];
            const V along = r.dx * cone.axis.x + r.dy * cone.axis.y + r.dz * cone.axis.z;
            tested &= laneBits((along >= cone.cosine) | (r.originSphere == T(k)));
            if (!tested) continue;
        }
        const PacketRoots<T> roots = intersectPacket(spheres, k, r, tested);
        const auto inward = roots.self & r.intoOrigin & maskFromBits<T>(lanes);
        if (!roots.valid && (!mayGoIn || !laneBits(inward))) continue;
        // A ray going into its own sphere crosses it before the light unless the
        // light is inside; where rounding loses the exit (a grazing ray) the exit
        // is at the origin, as in packetClosestHits().
        const auto exits = roots.hit & (roots.tFar > T(0));
        const auto crossesOwn = exits ? roots.tFar < distance : distance > T(0);
        const auto crossesOther = ((roots.tNear > T(0)) & (roots.tNear < distance)) |
                                  ((roots.tFar > T(0)) & (roots.tFar < distance));
        const auto take = inward ? crossesOwn : crossesOther & roots.hit;
        if (!laneBits(take)) continue;
        s = take ? s * transparency[k] : s;
        lanes &= ~laneBits(s == T(0));  // fully shadowed lanes are done
    }
    return s;
}

}  // namespace WHITTED_ISA_NAMESPACE
}  // namespace whitted
