// The hot tracing code: packets, intersection and shading, the bodies behind
// tracer.h's entry points. core/CMakeLists.txt compiles this file once per
// instruction set with WHITTED_ISA naming it; all of it lives in that set's
// namespace (isa_namespace.h), and only kTracerKernel is visible outside.
#include <algorithm>
#include <cmath>
#include <limits>

#include "tracer/bvh_traverse.h"
#include "tracer/isa_namespace.h"
#include "tracer/ray_packet.h"
#include "tracer/tracer_kernel.h"

// The per-ISA objects get WHITTED_ISA, _MARCH and _TUNE from CMake; built
// with the project's own flags (WHITTED_NATIVE), this is the "native" kernel.
#ifdef WHITTED_ISA_MARCH
#define WHITTED_KERNEL_NAME WHITTED_ISA_STR(WHITTED_ISA)
#else
#define WHITTED_KERNEL_NAME "native"
#define WHITTED_ISA_MARCH "native"
#define WHITTED_ISA_TUNE "native"
#endif

namespace whitted {
inline namespace WHITTED_ISA_NAMESPACE {

namespace {

template <typename T>
std::optional<Hit<T>> kernelClosestHit(const PreparedScene<T>& s, const Ray<T>& ray, T tMax) {
    RayPacket<T> packet;
    packet.set(0, ray.origin, ray.dir, ray.originSphere, ray.intoOrigin);
    packet.fromCamera = ray.fromCamera;
    typename Simd<T>::type t, k;
    sceneClosestHits(s.spheres, s.useBvh ? s.bvh.get() : nullptr, packet, t, k);
    if (k[0] < T(0) || !(t[0] < tMax)) return std::nullopt;
    return Hit<T>{t[0], static_cast<int>(k[0])};
}

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
    V hi, lo, hi2, e, ph, pl;
    exact::twoSum<V>(cAxis, sign * g.radius, hi, lo);
    lo = lo + (cAxisLo + sign * g.radiusLo);
    exact::twoSum<V>(hi, -sign * drop, hi2, e);
    exact::twoSum<V>(hi2, lo + e, hi, lo);
    // In cells, plus the frame origin's fraction of a cell.
    const Vec3x<T>& fh = g.checkerFrameFraction;
    const Vec3x<T>& fl = g.checkerFrameFractionLo;
    const V fAxis = isX ? fh.x : (isY ? fh.y : fh.z);
    const V fAxisLo = isX ? fl.x : (isY ? fl.y : fl.z);
    // (hi + lo) / size as q1 + q2: q1 from the rounded 1/size, q2 from the exact
    // remainder (hi + lo) - q1 * size, so the pair is right to ~eps^2 without a
    // division (1/size alone is inexact for sizes such as 50).
    const V q1 = hi * g.checkerInvSize;
    twoProductLanes<V, T>(q1, g.checkerSize, ph, pl);
    const V q2 = ((((hi - ph) - pl) + lo) - q1 * g.checkerSizeLo) * g.checkerInvSize;
    exact::twoSum<V>(q1, fAxis, hi2, e);
    exact::twoSum<V>(hi2, (e + fAxisLo) + q2, hi, lo);
    const V f = laneFloor(hi);
    const V steepCell = (f == hi) & (lo < T(0)) ? f - T(1) : f;  // floorOfPair()
    const Vec3x<T>& frac = g.checkerFrameFraction;
    const V cx = isX ? steepCell : laneFloor(frac.x + p.x * g.checkerInvSize);
    const V cy = isY ? steepCell : laneFloor(frac.y + p.y * g.checkerInvSize);
    const V cz = isZ ? steepCell : laneFloor(frac.z + p.z * g.checkerInvSize);
    auto odd = [](const V& cell) {
        const V half = cell * T(0.5);
        return half != laneFloor(half);
    };
    const Vec3x<T>& parity = g.checkerFrameParity;  // the frame origin's whole cells
    const auto oddCell = ((odd(cx) ^ (parity.x != T(0))) ^ (odd(cy) ^ (parity.y != T(0)))) ^
                         (odd(cz) ^ (parity.z != T(0)));
    return select(oddCell, g.checkerColor, g.diffuse);
}

template <typename T>
void tracePacket(const PreparedScene<T>& s, const RayPacket<T>& rays, int depth, Vec3x<T>& radiance,
                 RayCounts& counts);

// Where the lanes that hit are on their surfaces: the point, the normal
// facing the ray, and on which side the ray came from.
template <typename T>
struct SurfacePoint {
    using V = typename Simd<T>::type;
    Vec3x<T> d, p, outward, n;
    decltype(V{} > V{}) inside;  // the ray hit the surface from within
};

template <typename T>
SurfacePoint<T> surfacePoint(const RayPacket<T>& rays, const typename Simd<T>::type& tHit,
                             const LaneMaterials<T>& g) {
    SurfacePoint<T> sp;
    sp.d = rays.dirs();
    sp.p = rays.origins() + tHit * sp.d;
    // Normalised, not divided by the radius: p is off the surface by its
    // rounding error, and a normal that is not unit length makes reflect()
    // lengthen the ray, which puts the next hit further off; inside glass that
    // error grew sevenfold per internal reflection until float renders showed
    // speckles.
    sp.outward = normalize(sp.p - g.centre);
    sp.inside = dot(sp.d, sp.outward) > T(0);
    sp.n = select(sp.inside, -sp.outward, sp.outward);
    return sp;
}

// Each light's diffuse and specular share at the lanes that hit, dimmed by
// the transmittance of what lies between (one shadow packet per light).
template <typename T, typename Mask>
void addDirectLight(const PreparedScene<T>& s, const LaneMaterials<T>& g, const SurfacePoint<T>& sp,
                    const Mask& hit, const typename Simd<T>::type& kHit, const Vec3x<T>& kd,
                    Vec3x<T>& radiance, RayCounts& counts) {
    using V = typename Simd<T>::type;
    const Vec3x<T>& p = sp.p;
    const Vec3x<T>& n = sp.n;
    for (const PreparedLight<T>& light : s.lights) {
        Vec3x<T> l = Vec3x<T>::broadcast(light.position) - p;
        const V distance = laneSqrt(dot(l, l));
        l = l * (T(1) / distance);
        const V nl = dot(n, l);
        const auto lit = hit & g.lit & (distance > T(0)) & (nl > T(0));
        const unsigned litLanes = laneBits(lit);
        if (!litLanes) continue;
        counts.shadow += __builtin_popcount(litLanes);
        // The shadow ray goes into the sphere when it leaves p against the outward normal.
        const RayPacket<T> shadow =
            RayPacket<T>::of(p, l, kHit, dot(l, sp.outward) < T(0), litLanes);
        const V sj = sceneTransmittance(s.spheres, s.transparency, s.useBvh ? s.bvh.get() : nullptr,
                                        shadow, distance, litLanes);
        const auto shaded = lit & (sj != T(0));
        if (!laneBits(shaded)) continue;
        Vec3x<T> term = kd * nl;
        const auto glossy = shaded & (g.specular > T(0));
        if (laneBits(glossy)) {
            const V nh = dot(n, normalize(l - sp.d));
            const auto highlight = glossy & (nh > T(0));
            V spec = powLanes<T>(nh, highlight & (g.shininessInt >= 0) ? g.shininessInt : 0);
            for (unsigned bits = laneBits(highlight & (g.shininessInt < 0)); bits;
                 bits &= bits - 1) {
                const int i = __builtin_ctz(bits);
                spec[i] = std::pow(nh[i], g.shininess[i]);
            }
            const V add = g.specular * spec;
            term = select(highlight, term + Vec3x<T>{add, add, add}, term);
        }
        const Vec3x<T> colour = Vec3x<T>::broadcast(light.color);
        radiance = select(shaded, radiance + (sj * colour) * term, radiance);
    }
}

// The refracted and reflected shares at the lanes that hit, each traced as a
// packet one level deeper: refraction first, then reflection, each added in
// the order of the formula.
template <typename T, typename Mask>
void addSecondaryRays(const PreparedScene<T>& s, const LaneMaterials<T>& g,
                      const SurfacePoint<T>& sp, const Mask& hit,
                      const typename Simd<T>::type& kHit, int depth, Vec3x<T>& radiance,
                      RayCounts& counts) {
    using V = typename Simd<T>::type;
    const Vec3x<T>& d = sp.d;
    const Vec3x<T>& n = sp.n;
    V reflectWeight = g.reflectivity;
    const auto glass = hit & (g.transparency > T(0));
    if (laneBits(glass)) {
        const V eta = sp.inside ? g.ior : T(1) / g.ior;
        const V cosi = -dot(d, n);
        const V k = T(1) - eta * eta * (T(1) - cosi * cosi);
        const auto passes = glass & (k >= T(0));
        // Total internal reflection: the refracted share follows the reflected
        // ray, which is traced once for both shares.
        reflectWeight = glass & ~(k >= T(0)) ? reflectWeight + g.transparency : reflectWeight;
        if (const unsigned bits = laneBits(passes)) {
            const V root = laneSqrt(passes ? k : V{});
            const Vec3x<T> t = normalize(eta * d + (eta * cosi - root) * n);
            // Refracted rays cross the surface: into the sphere from outside, out from inside.
            const RayPacket<T> refracted = RayPacket<T>::of(sp.p, t, kHit, ~sp.inside, bits);
            counts.refraction += __builtin_popcount(bits);
            Vec3x<T> sub;
            tracePacket(s, refracted, depth + 1, sub, counts);
            radiance = select(passes, radiance + g.transparency * sub, radiance);
        }
    }
    const auto mirror = hit & (reflectWeight > T(0));
    if (const unsigned bits = laneBits(mirror)) {
        const Vec3x<T> r = d - (T(2) * dot(d, n)) * n;  // reflect(d, n)
        const RayPacket<T> reflected = RayPacket<T>::of(sp.p, r, kHit, sp.inside, bits);
        counts.reflection += __builtin_popcount(bits);
        Vec3x<T> sub;
        tracePacket(s, reflected, depth + 1, sub, counts);
        radiance = select(mirror, radiance + reflectWeight * sub, radiance);
    }
}

// Radiance along every ray of a packet at the given depth: the Whitted sum of
// SPEC §3, computed for all lanes at once, with the shadow, reflected and
// refracted rays of all lanes traced as packets.
template <typename T>
void tracePacket(const PreparedScene<T>& s, const RayPacket<T>& rays, int depth, Vec3x<T>& radiance,
                 RayCounts& counts) {
    using V = typename Simd<T>::type;
    V tHit, kHit;
    sceneClosestHits(s.spheres, s.useBvh ? s.bvh.get() : nullptr, rays, tHit, kHit);
    radiance = Vec3x<T>::broadcast(s.background);
    const auto hit = (kHit >= T(0)) & maskFromBits<T>(rays.active);
    const unsigned lanes = laneBits(hit);
    if (!lanes) return;

    const LaneMaterials<T> g = gatherMaterials(s, kHit, lanes);
    const SurfacePoint<T> sp = surfacePoint(rays, tHit, g);
    Vec3x<T> kd = g.diffuse;
    if (laneBits(g.checker & hit)) kd = select(g.checker, checkerLanes(g, sp.p, sp.outward), kd);
    radiance = select(hit, Vec3x<T>::broadcast(s.ambient) * kd, radiance);
    addDirectLight(s, g, sp, hit, kHit, kd, radiance, counts);
    if (depth < s.maxDepth) addSecondaryRays(s, g, sp, hit, kHit, depth, radiance, counts);
}

template <typename T>
Vec<T> kernelTraceRay(const PreparedScene<T>& s, const Ray<T>& ray, int depth, RayCounts& counts) {
    RayPacket<T> packet;
    packet.set(0, ray.origin, ray.dir, ray.originSphere, ray.intoOrigin);
    packet.fromCamera = ray.fromCamera;
    Vec3x<T> radiance;
    tracePacket(s, packet, depth, radiance, counts);
    return radiance.lane(0);
}

// Camera rays through image-plane positions (x, y) = (i + u, j + v) for the
// first m lanes: cameraDirection() for every lane at once, operation for operation.
template <typename T>
void traceCameraPacket(const PreparedScene<T>& s, typename Simd<T>::type x,
                       typename Simd<T>::type y, int m, Vec3x<T>& radiance, RayCounts& counts) {
    using V = typename Simd<T>::type;
    const CameraBasis<T>& cam = s.camera;
    x = (x / T(cam.width) * T(2) - T(1)) * cam.tanHalfFov * cam.aspect;
    y = (T(1) - y / T(cam.height) * T(2)) * cam.tanHalfFov;
    const Vec3x<T> dir =
        normalize(Vec3x<T>::broadcast(cam.forward) + x * Vec3x<T>::broadcast(cam.right) +
                  y * Vec3x<T>::broadcast(cam.up));
    const RayPacket<T> packet =
        RayPacket<T>::of(Vec3x<T>::broadcast(cam.origin), dir, V{} - T(1),
                         typename RayPacket<T>::Mask{}, (1u << m) - 1, true);
    counts.camera += m;
    tracePacket(s, packet, 0, radiance, counts);
}

// Camera rays for `count` samples in packets; place(first, m, x, y) puts the
// image-plane positions (i + u, j + v) of samples first .. first+m-1 in lanes.
template <typename T, typename Place>
void traceCameraPackets(const PreparedScene<T>& s, int count, Vec<T>* radiance, RayCounts& counts,
                        Place place) {
    constexpr int W = RayPacket<T>::kWidth;
    using V = typename Simd<T>::type;
    for (int first = 0; first < count; first += W) {
        const int m = std::min(W, count - first);
        V x{}, y{};
        place(first, m, x, y);
        Vec3x<T> out;
        traceCameraPacket(s, x, y, m, out, counts);
        for (int l = 0; l < m; ++l) radiance[first + l] = out.lane(l);
    }
}

template <typename T>
void kernelCameraSamples(const PreparedScene<T>& s, const CameraSample<T>* samples, int count,
                         Vec<T>* radiance, RayCounts& counts) {
    using V = typename Simd<T>::type;
    traceCameraPackets(s, count, radiance, counts, [&](int first, int m, V& x, V& y) {
        for (int l = 0; l < m; ++l) {
            const CameraSample<T>& cs = samples[first + l];
            x[l] = T(cs.i) + cs.u;
            y[l] = T(cs.j) + cs.v;
        }
    });
}

template <typename T>
void kernelCameraRow(const PreparedScene<T>& s, int y, int x0, int count, int n, Vec<T>* radiance,
                     RayCounts& counts) {
    using V = typename Simd<T>::type;
    V laneIndex{};
    for (int l = 0; l < RayPacket<T>::kWidth; ++l) laneIndex[l] = T(l);
    traceCameraPackets(s, count, radiance, counts, [&](int first, int m, V& px, V& py) {
        if (s.samplesPerPixel == 1) {  // pixel centres, as pixelSample() gives them
            px = (laneIndex + T(x0 + first)) + T(0.5);
            py = V{} + (T(y) + T(0.5));
            return;
        }
        for (int l = 0; l < m; ++l) {
            const CameraSample<T> cs = pixelSample(s, x0 + first + l, y, n);
            px[l] = T(cs.i) + cs.u;
            py[l] = T(cs.j) + cs.v;
        }
    });
}

}  // namespace

// Constant-initialised, so loading an object built for a newer CPU runs none of
// its instructions until the dispatcher has chosen it.
extern const TracerKernel kTracerKernel;
constinit const TracerKernel kTracerKernel{
    .name = WHITTED_KERNEL_NAME,
    .isa = WHITTED_ISA_MARCH,
    .tune = WHITTED_ISA_TUNE,
    .vectorBytes = kSimdBytes,
    .floats = {kernelClosestHit<float>, kernelTraceRay<float>, kernelCameraSamples<float>,
               kernelCameraRow<float>},
    .doubles = {kernelClosestHit<double>, kernelTraceRay<double>, kernelCameraSamples<double>,
                kernelCameraRow<double>},
};

}  // namespace WHITTED_ISA_NAMESPACE
}  // namespace whitted
