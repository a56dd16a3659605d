// What the packet kernel (tracer_kernel.cpp) knows of each lane's hit: the
// sphere's material gathered into lanes, the checker colour at the hit point,
// whole powers for the highlight. Compiled into each instruction set's
// kernel, so it lives in that set's namespace (isa_namespace.h).
#pragma once

#include <cmath>

#include "tracer/isa_namespace.h"
#include "tracer/ray_packet.h"
#include "tracer/simd.h"
#include "tracer/simd_vec3.h"
#include "tracer/sphere_intersect.h"
#include "tracer/tracer.h"

namespace whitted {
inline namespace WHITTED_ISA_NAMESPACE {

// x^n per lane for whole exponents n >= 0, by squaring: several times faster
// than std::pow for the shininess values people use (10 to 200).
template <typename T>
typename Simd<T>::type powLanes(typename Simd<T>::type x, typename RayPacket<T>::Mask n) {
    using V = typename Simd<T>::type;
    V result = V{} + T(1);
    while (laneBits(n > 0)) {
        result = (n & 1) != 0 ? result * x : result;
        x = x * x;
        n >>= 1;
    }
    return result;
}

// The sphere and material of every lane's hit, gathered into lanes.
template <typename T>
struct LaneMaterials {
    using V = typename Simd<T>::type;
    using Mask = typename RayPacket<T>::Mask;
    Vec3x<T> centre, centreLo, diffuse;
    // Not zeroed: gatherMaterials() writes every field of every lane.
    V specular, reflectivity, transparency, ior;
    Mask lit, checker;
    Mask shininessInt;  // the whole shininess, or -1 for lanes that need std::pow
    V shininess;
    Vec3x<T> checkerColor, checkerFrameFraction, checkerFrameFractionLo, checkerFrameParity;
    V checkerInvSize, checkerSize, checkerSizeLo, radius, radiusLo, rrHi, rrLo;
};

// Writes one hit's sphere and material into a LaneMaterials, field by field,
// through `put` (one lane, or all lanes at once).
template <typename T, typename Put>
void describeHit(const PreparedScene<T>& s, int k, LaneMaterials<T>& g, Put put) {
    using Lane = typename RayPacket<T>::MaskLane;
    const PreparedMaterial<T>& m = s.materials[s.material[k]];
    put(g.centre, s.spheres.centre[k]);
    put(g.centreLo, s.spheres.centreLo[k]);
    put(g.diffuse, m.diffuse);
    put(g.specular, m.specular);
    put(g.reflectivity, m.reflectivity);
    put(g.transparency, m.transparency);
    put(g.ior, m.ior);
    put(g.lit, m.lit ? Lane(-1) : Lane(0));
    put(g.checker, m.checkerInvSize != T(0) ? Lane(-1) : Lane(0));
    put(g.shininessInt, Lane(m.integerShininess));
    put(g.shininess, m.shininess);
    put(g.checkerColor, m.checkerColor);
    put(g.checkerInvSize, m.checkerInvSize);
    put(g.checkerSize, m.checkerSize);
    put(g.checkerSizeLo, m.checkerSizeLo);
    put(g.checkerFrameFraction, m.checkerFrameFraction);
    put(g.checkerFrameFractionLo, m.checkerFrameFractionLo);
    put(g.checkerFrameParity, m.checkerFrameParity);
    put(g.radius, s.spheres.radius[k]);
    put(g.radiusLo, s.spheres.radiusLo[k]);
    put(g.rrHi, s.spheres.rrHi[k]);
    put(g.rrLo, s.spheres.rrLo[k]);
}

// Every field of every lane (those of `lanes` that miss too) from the sphere
// of the lowest lane of `lanes`, then, sphere by sphere, the lanes that hit
// another. Neighbouring rays mostly hit one sphere, and a scene has few near
// one packet: a broadcast and a blend per field and sphere cost less than the
// scalar stores of lane by lane (about 40 a lane).
template <typename T>
LaneMaterials<T> gatherMaterials(const PreparedScene<T>& s, const typename Simd<T>::type& kHit,
                                 unsigned lanes) {
    LaneMaterials<T> g;
    const T first = kHit[__builtin_ctz(lanes)];
    describeHit(s, static_cast<int>(first), g, [](auto& field, const auto& value) {
        using Field = std::remove_reference_t<decltype(field)>;
        if constexpr (requires { field.setLane(0, value); })
            field = Field::broadcast(value);
        else
            field = Field{} + value;
    });
    for (unsigned rest = lanes & ~laneBits(kHit == first); rest;) {
        const T k = kHit[__builtin_ctz(rest)];
        const auto same = kHit == k;
        describeHit(s, static_cast<int>(k), g, [&same](auto& field, const auto& value) {
            using Field = std::remove_reference_t<decltype(field)>;
            if constexpr (requires { field.setLane(0, value); })
                field = select(same, Field::broadcast(value), field);
            else
                field = same ? Field{} + value : field;
        });
        rest &= ~laneBits(same);
    }
    return g;
}

// a * b == p + e exactly, per lane (Dekker's split: GCC's vectors have no fma).
template <typename V, typename T>
void twoProductLanes(const V& a, const V& b, V& p, V& e) {
    constexpr T splitter = sizeof(T) == 4 ? T(4097) : T(134217729);  // 2^12+1, 2^27+1
    p = a * b;
    const V ta = splitter * a, tb = splitter * b;
    const V ahi = ta - (ta - a), bhi = tb - (tb - b);
    const V alo = a - ahi, blo = b - bhi;
    e = ((ahi * bhi - p) + ahi * blo + alo * bhi) + alo * blo;
}

// The cell the length hi + lo (a two-term sum) falls in along an axis whose
// frame origin is fAxis + fAxisLo cells from the world's: floor((hi + lo) /
// size + f), right to the last bit (floorOfPair()).
template <typename T, typename V = typename Simd<T>::type>
[[gnu::always_inline]] inline V cellOfPair(const LaneMaterials<T>& g, V hi, V lo, const V& fAxis,
                                           const V& fAxisLo) {
    // (hi + lo) / size as q1 + q2: q1 from the rounded 1/size, q2 from the exact
    // remainder (hi + lo) - q1 * size, so the pair is right to ~eps^2 without a
    // division (1/size alone is inexact for sizes such as 50).
    V ph, pl, sum, e;
    const V q1 = hi * g.checkerInvSize;
    twoProductLanes<V, T>(q1, g.checkerSize, ph, pl);
    const V q2 = ((((hi - ph) - pl) + lo) - q1 * g.checkerSizeLo) * g.checkerInvSize;
    exact::twoSum<V>(q1, fAxis, sum, e);
    exact::twoSum<V>(sum, (e + fAxisLo) + q2, hi, lo);
    const V f = laneFloor(hi);
    return (f == hi) & (lo < T(0)) ? f - T(1) : f;
}

// kd(P) of SPEC §3 for every lane: checker colour where floor(Px/s) +
// floor(Py/s) + floor(Pz/s) is odd, diffuse where even.
//
// The cell index along the axis where the surface is steepest comes from the
// sphere's own equation rather than from the hit point. Why: the seed's floor
// touches the cell boundary plane y = -0.5 at the origin and drops below it by
// only (x^2 + z^2) / 2r, about 3e-8 near the camera, while the hit point's y
// carries the ray's rounding error (1e-7 in float), so its cell index would
// flicker there. Along that axis the surface is
// centre + r - (a^2 + b^2) / (r + sqrt(r^2 - a^2 - b^2)), kept exactly as a
// two-term sum, so the index comes out right to the last bit.
template <typename T>
Vec3x<T> checkerLanes(const LaneMaterials<T>& g, const Vec3x<T>& p, const Vec3x<T>& outward) {
    using V = typename Simd<T>::type;
    const V ax = outward.x < T(0) ? -outward.x : outward.x;
    const V ay = outward.y < T(0) ? -outward.y : outward.y;
    const V az = outward.z < T(0) ? -outward.z : outward.z;
    const auto xOverY = ax >= ay;
    const auto isZ = az > (xOverY ? ax : ay);
    const auto isX = xOverY & ~isZ;
    const auto isY = ~xOverY & ~isZ;
    // Across-axis components a, b as steepAxisCell() picks them.
    const V qa = isX ? p.y : (isY ? p.z : p.x), qb = isX ? p.z : (isY ? p.x : p.y);
    const V ca = isX ? g.centre.y : (isY ? g.centre.z : g.centre.x);
    const V cb = isX ? g.centre.z : (isY ? g.centre.x : g.centre.y);
    const V caLo = isX ? g.centreLo.y : (isY ? g.centreLo.z : g.centreLo.x);
    const V cbLo = isX ? g.centreLo.z : (isY ? g.centreLo.x : g.centreLo.y);
    const V cAxis = isX ? g.centre.x : (isY ? g.centre.y : g.centre.z);
    const V cAxisLo = isX ? g.centreLo.x : (isY ? g.centreLo.y : g.centreLo.z);
    const V oAxis = isX ? outward.x : (isY ? outward.y : outward.z);
    const V da = (qa - ca) - caLo, db = (qb - cb) - cbLo;
    const V across = da * da + db * db;
    const V rest = (g.rrHi - across) + g.rrLo;
    const V drop = across / (g.radius + (rest > T(0) ? laneSqrt(rest > T(0) ? rest : V{}) : V{}));
    const V sign = oAxis >= T(0) ? V{} + T(1) : V{} - T(1);
    // The surface along the axis, centre + sign * (r - drop), as the pair hi + lo,
    // with the centre's and the radius's low terms (a float floor of radius 1e9).
    // The sphere's extreme, centre + sign * r, is made a normalised pair before
    // the drop is taken off: added to an unnormalised low term (the seed's floor
    // in float: -0.8515625 + 0.0015625) a drop of 1e-11 would be rounded away.
    V hi, lo, hi2, e, loHi, loLo;
    exact::twoSum<V>(cAxis, sign * g.radius, hi, lo);
    exact::twoSum<V>(cAxisLo, sign * g.radiusLo, loHi, loLo);
    exact::twoSum<V>(hi, (lo + loHi) + loLo, hi2, e);
    exact::twoSum<V>(hi2, -sign * drop, hi, lo);
    exact::twoSum<V>(hi, lo + e, hi, lo);
    // In cells, plus the frame origin's fraction of a cell.
    const Vec3x<T>& fh = g.checkerFrameFraction;
    const Vec3x<T>& fl = g.checkerFrameFractionLo;
    const V steepCell =
        cellOfPair(g, hi, lo, isX ? fh.x : (isY ? fh.y : fh.z), isX ? fl.x : (isY ? fl.y : fl.z));
    const V cx = isX ? steepCell : laneFloor(fh.x + p.x * g.checkerInvSize);
    const V cy = isY ? steepCell : laneFloor(fh.y + p.y * g.checkerInvSize);
    const V cz = isZ ? steepCell : laneFloor(fh.z + p.z * g.checkerInvSize);
    auto odd = [](const V& cell) {
        const V half = cell * T(0.5);
        return half != laneFloor(half);
    };
    const Vec3x<T>& parity = g.checkerFrameParity;  // the frame origin's whole cells
    const auto oddCell = ((odd(cx) ^ (parity.x != T(0))) ^ (odd(cy) ^ (parity.y != T(0)))) ^
                         (odd(cz) ^ (parity.z != T(0)));
    return select(oddCell, g.checkerColor, g.diffuse);
}

}  // namespace WHITTED_ISA_NAMESPACE
}  // namespace whitted
