// Ray-sphere intersection that keeps its precision for huge, tiny and far spheres.
//
// Solve t^2 + 2bt + c = 0 with b = f.d, c = |f|^2 - r^2, f = o - centre, |d| = 1.
// Two cancellations ruin the textbook version:
//  * far small spheres: b^2 - c subtracts two nearly equal numbers. The
//    discriminant is taken as r^2 - |f - b d|^2 instead (Ray Tracing Gems, ch. 7).
//  * origins close to a big sphere (the seed's floor, radius 99999): c is the
//    difference of two numbers near 1e10; in float their spacing is 1024. There c is
//    computed with error-free transformations (TwoSum, TwoProduct), still in T.
// The near root is c/q, never -b - sqrt(...), so it does not cancel either.
#pragma once

#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "tracer/isa_namespace.h"
#include "tracer/simd.h"

namespace whitted {

template <typename T>
using Vec = glm::vec<3, T, glm::defaultp>;

template <typename T>
struct SphereRoots {
    T tNear;  // tNear <= tFar; either may be negative (behind the origin)
    T tFar;
};

inline namespace WHITTED_ISA_NAMESPACE {

namespace exact {

// s + e == a + b exactly (Knuth's TwoSum).
template <typename T>
inline void twoSum(T a, T b, T& s, T& e) {
    s = a + b;
    const T bb = s - a;
    e = (a - (s - bb)) + (b - bb);
}

// p + e == a * b exactly.
template <typename T>
inline void twoProduct(T a, T b, T& p, T& e) {
    p = a * b;
#ifdef __FMA__
    e = std::fma(a, b, -p);
#else
    // Dekker's split: each factor == hi + lo with halves short enough to multiply exactly.
    constexpr T splitter = sizeof(T) == 4 ? T(4097) : T(134217729);  // 2^12+1, 2^27+1
    const T ta = splitter * a, tb = splitter * b;
    const T ahi = ta - (ta - a), bhi = tb - (tb - b);
    const T alo = a - ahi, blo = b - bhi;
    e = ((ahi * bhi - p) + ahi * blo + alo * bhi) + alo * blo;
#endif
}

template <typename T>
inline void twoSquare(T a, T& p, T& e) {
    twoProduct(a, a, p, e);
}

// twoSquare() for every lane of a SIMD vector V of T, by the same operations.
template <typename V, typename T>
inline void twoSquareLanes(const V& a, V& p, V& e) {
    p = a * a;
#ifdef __FMA__
    e = laneFma(a, a, -p);
#else
    constexpr T splitter = sizeof(T) == 4 ? T(4097) : T(134217729);  // 2^12+1, 2^27+1
    const V ta = splitter * a;
    const V ahi = ta - (ta - a);
    const V alo = a - ahi;
    e = ((ahi * ahi - p) + ahi * alo + alo * ahi) + alo * alo;
#endif
}

}  // namespace exact

// |o - centre|^2 - r^2 to nearly full precision of T, given the centre as
// centre + centreLo and r^2 as rrHi + rrLo (two-term values: what T drops of a
// double scene, see SphereSet::add).
template <typename T>
T accurateOffsetSquared(const Vec<T>& o, const Vec<T>& centre, const Vec<T>& centreLo, T rrHi,
                        T rrLo) {
    T fh[3], fl[3], p[3], pe[3];
    for (int i = 0; i < 3; ++i) {
        exact::twoSum(o[i], -centre[i], fh[i], fl[i]);
        fl[i] -= centreLo[i];
        exact::twoSquare(fh[i], p[i], pe[i]);
    }
    // Sum p0 + p1 + p2 - rrHi with every rounding error carried along (Sum2).
    T s = p[0], err = 0, e;
    exact::twoSum(s, p[1], s, e);
    err += e;
    exact::twoSum(s, p[2], s, e);
    err += e;
    exact::twoSum(s, -rrHi, s, e);
    err += e;
    T small = pe[0] + pe[1] + pe[2] - rrLo;
    for (int i = 0; i < 3; ++i) small += fl[i] * (T(2) * fh[i] + fl[i]);
    return s + (err + small);
}

// accurateOffsetSquared() for every lane of a SIMD vector V of T, operation
// for operation, so each lane gets what the scalar function gives its origin
// and sphere: a sphere a lane (the camera terms of many spheres) or, below,
// one sphere for every lane.
template <typename V>
V accurateOffsetSquaredOfLanes(const V (&o)[3], const V (&centre)[3], const V (&centreLo)[3],
                               const V& rrHi, const V& rrLo) {
    using T = std::remove_cvref_t<decltype(rrHi[0])>;
    V fh[3], fl[3], p[3], pe[3];
    for (int i = 0; i < 3; ++i) {
        exact::twoSum<V>(o[i], -centre[i], fh[i], fl[i]);  // -c exactly, as its sign
        fl[i] = fl[i] - centreLo[i];
        exact::twoSquareLanes<V, T>(fh[i], p[i], pe[i]);
    }
    V s = p[0], err{}, e;
    exact::twoSum<V>(s, p[1], s, e);
    err = err + e;
    exact::twoSum<V>(s, p[2], s, e);
    err = err + e;
    exact::twoSum<V>(s, -rrHi, s, e);
    err = err + e;
    V small = pe[0] + pe[1] + pe[2] - rrLo;
    for (int i = 0; i < 3; ++i) small = small + fl[i] * (T(2) * fh[i] + fl[i]);
    return s + (err + small);
}

template <typename V, typename T>
V accurateOffsetSquaredLanes(const V (&o)[3], const Vec<T>& centre, const Vec<T>& centreLo, T rrHi,
                             T rrLo) {
    const V c[3] = {V{} + centre[0], V{} + centre[1], V{} + centre[2]};
    const V cLo[3] = {V{} + centreLo[0], V{} + centreLo[1], V{} + centreLo[2]};
    return accurateOffsetSquaredOfLanes(o, c, cLo, V{} + rrHi, V{} + rrLo);
}

// Roots of the ray o + t d (d unit length) against the sphere, or nothing on a miss.
// The sphere's centre is centre + centreLo and its squared radius rrHi + rrLo
// (see splitRadiusSquared). `knownC`, if given, is accurateOffsetSquared() for
// this origin, cached by the caller for rays sharing an origin (camera rays).
template <typename T>
inline std::optional<SphereRoots<T>> intersectSphere(const Vec<T>& o, const Vec<T>& d,
                                                     const Vec<T>& centre, const Vec<T>& centreLo,
                                                     T rrHi, T rrLo, const T* knownC = nullptr) {
    const Vec<T> f = o - centre;
    const T b = f.x * d.x + f.y * d.y + f.z * d.z;
    const T ff = f.x * f.x + f.y * f.y + f.z * f.z;
    T c = knownC ? *knownC : ff - rrHi;
    // Outside beyond any rounding doubt and moving away: a miss, found cheaply.
    if (b > T(0) && c > ff * (T(16) * std::numeric_limits<T>::epsilon())) return std::nullopt;
    T disc;
    // Cancellation of more than 4 bits in c: the origin is near this sphere's surface
    // relative to its size, so c must be exact enough, and b^2 - c then has no
    // cancellation of its own.
    if (std::fabs(c) < ff * T(0.0625)) {
        if (!knownC) c = accurateOffsetSquared(o, centre, centreLo, rrHi, rrLo);
        disc = b * b - c;
    } else {
        const Vec<T> perp = f - b * d;
        disc = rrHi - (perp.x * perp.x + perp.y * perp.y + perp.z * perp.z);
    }
    if (!(disc >= T(0))) return std::nullopt;
    const T root = std::sqrt(disc);
    const T q = -b - (b < T(0) ? -root : root);  // no cancellation: -b and the root agree in sign
    if (q == T(0)) return SphereRoots<T>{T(0), T(0)};  // origin at the centre of a point sphere
    const T t0 = c / q;
    const T t1 = q;
    return t0 < t1 ? SphereRoots<T>{t0, t1} : SphereRoots<T>{t1, t0};
}

// A sphere whose centre T holds exactly.
template <typename T>
inline std::optional<SphereRoots<T>> intersectSphere(const Vec<T>& o, const Vec<T>& d,
                                                     const Vec<T>& centre, T rrHi, T rrLo,
                                                     const T* knownC = nullptr) {
    return intersectSphere(o, d, centre, Vec<T>(T(0)), rrHi, rrLo, knownC);
}

// rrHi + rrLo == r*r exactly.
template <typename T>
inline void splitRadiusSquared(T r, T& rrHi, T& rrLo) {
    exact::twoSquare(r, rrHi, rrLo);
}

}  // namespace WHITTED_ISA_NAMESPACE
}  // namespace whitted
