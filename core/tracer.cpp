#include "tracer.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ray_packet.h"
#include "sampling.h"

namespace whitted {

template <typename T>
PreparedScene<T> prepareScene(const Scene& scene) {
    PreparedScene<T> s;
    const RenderSettings& r = scene.render;
    s.camera = makeCameraBasis<T>(scene.camera, r.width, r.height);
    s.width = r.width;
    s.height = r.height;
    s.maxDepth = r.maxDepth;
    s.samplesPerPixel = r.samplesPerPixel;
    s.background = Vec<T>(scene.background);
    s.ambient = Vec<T>(scene.ambient);
    for (const Material& m : scene.materials) {
        PreparedMaterial<T> pm;
        pm.diffuse = Vec<T>(m.diffuse);
        if (m.checker) {
            pm.checkerColor = Vec<T>(m.checker->color);
            pm.checkerInvSize = T(1.0 / m.checker->size);
        }
        pm.specular = T(m.specular);
        pm.shininess = T(m.shininess);
        pm.reflectivity = T(m.reflectivity);
        pm.transparency = T(m.transparency);
        pm.ior = T(m.ior);
        if (m.shininess == std::floor(m.shininess) && m.shininess <= 1024)
            pm.integerShininess = static_cast<int>(m.shininess);
        const bool diffuseLit =
            m.diffuse != Vec3(0.0) || (m.checker && m.checker->color != Vec3(0.0));
        pm.lit = diffuseLit || m.specular > 0;
        s.materials.push_back(pm);
    }
    for (const Light& l : scene.lights) {
        const Vec3 c = l.color * l.intensity;
        if (c == Vec3(0.0)) continue;  // a dark light adds nothing: no shadow rays for it
        s.lights.push_back({Vec<T>(l.position), Vec<T>(c)});
    }
    std::vector<T> cameraC;
    for (const Sphere& sp : scene.spheres) {
        T hi, lo;
        splitRadiusSquared(T(sp.radius), hi, lo);
        s.centre.push_back(Vec<T>(sp.center));
        s.radius.push_back(T(sp.radius));
        s.rrHi.push_back(hi);
        s.rrLo.push_back(lo);
        s.material.push_back(findMaterial(scene, sp.material));
        s.transparency.push_back(s.materials[s.material.back()].transparency);
        cameraC.push_back(accurateOffsetSquared(s.camera.origin, s.centre.back(), hi, lo));
    }
    s.blocks.assign(s.centre, s.rrHi, s.rrLo, cameraC);
    return s;
}

namespace {

// The lanes of block `bi` a ray must test: all but the sphere it leaves outwards.
template <typename T>
unsigned lanesToTest(int bi, const Ray<T>& ray) {
    constexpr int W = SphereBlock<T>::kWidth;
    unsigned lanes = (1u << W) - 1;
    if (ray.originSphere / W == bi && !ray.intoOrigin)
        lanes &= ~(1u << (ray.originSphere % W));  // convex: leaving it, it cannot be hit again
    return lanes;
}

}  // namespace

template <typename T>
std::optional<Hit<T>> closestHit(const PreparedScene<T>& s, const Ray<T>& ray, T tMax) {
    constexpr int W = SphereBlock<T>::kWidth;
    std::optional<Hit<T>> best;
    const int blocks = static_cast<int>(s.blocks.blocks.size());
    for (int bi = 0; bi < blocks; ++bi) {
        const BlockRoots<T> r = intersectBlock(s.blocks.blocks[bi], ray.origin, ray.dir,
                                               ray.fromCamera, lanesToTest(bi, ray));
        for (unsigned bits = r.valid; bits; bits &= bits - 1) {
            const int l = __builtin_ctz(bits);
            const int k = bi * W + l;
            // Going into its own sphere, a ray can only meet the far side.
            const T t =
                k == ray.originSphere ? r.tFar[l] : (r.tNear[l] > T(0) ? r.tNear[l] : r.tFar[l]);
            if (t > T(0) && t < tMax) {
                tMax = t;
                best = Hit<T>{t, k};
            }
        }
    }
    return best;
}

namespace {

template <typename T>
T dot3(const Vec<T>& a, const Vec<T>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

// x^n for a whole n by squaring: several times faster than std::pow for the
// shininess values people use (10 to 200).
template <typename T>
T powInt(T x, int n) {
    T result = 1;
    while (n > 0) {
        if (n & 1) result *= x;
        x *= x;
        n >>= 1;
    }
    return result;
}

template <typename T>
bool isOdd(T cell) {
    const T half = cell * T(0.5);
    return half != std::floor(half);
}

// floor(hi + lo) for a pair with |lo| <= ulp(hi) / 2.
template <typename T>
T floorOfPair(T hi, T lo) {
    const T f = std::floor(hi);
    return (f == hi && lo < T(0)) ? f - T(1) : f;
}

// The checker cell index along the axis where the surface is steepest, from
// the sphere's own equation rather than from the hit point.
//
// Why: the seed's floor touches the cell boundary plane y = -0.5 at the origin
// and drops below it by only (x^2 + z^2) / 2r, about 3e-8 near the camera. The
// hit point's y carries the ray's rounding error (1e-7 in float), so its cell
// index would flicker there. Along that axis the surface is
// centre + r - (a^2 + b^2) / (r + sqrt(r^2 - a^2 - b^2)), which is kept exactly
// as a two-term sum, so the index comes out right to the last bit.
template <typename T>
T steepAxisCell(const PreparedScene<T>& s, int k, const Vec<T>& p, const Vec<T>& outward, int axis,
                T invSize) {
    const int a = axis == 2 ? 0 : axis + 1, b = axis == 0 ? 2 : axis - 1;
    // Components by pointer: glm's operator[] branches on the index.
    const T* c = &s.centre[k].x;
    const T* q = &p.x;
    const T da = q[a] - c[a], db = q[b] - c[b];
    const T across = da * da + db * db;
    const T rest = (s.rrHi[k] - across) + s.rrLo[k];
    const T drop = across / (s.radius[k] + (rest > T(0) ? std::sqrt(rest) : T(0)));
    const T sign = (&outward.x)[axis] >= T(0) ? T(1) : T(-1);
    T hi, lo, hi2, e;
    exact::twoSum(c[axis], sign * s.radius[k], hi, lo);
    exact::twoSum(hi, -sign * drop, hi2, e);
    exact::twoSum(hi2, lo + e, hi, lo);
    T ph, pl;
    exact::twoProduct(hi, invSize, ph, pl);
    exact::twoSum(ph, pl + lo * invSize, hi, lo);
    return floorOfPair(hi, lo);
}

template <typename T>
Vec<T> diffuseAt(const PreparedScene<T>& s, int k, const PreparedMaterial<T>& m, const Vec<T>& p,
                 const Vec<T>& outward) {
    if (m.checkerInvSize == T(0)) return m.diffuse;
    int axis = std::fabs(outward.x) >= std::fabs(outward.y) ? 0 : 1;
    if (std::fabs(outward.z) > std::fabs((&outward.x)[axis])) axis = 2;
    bool odd = false;
    for (int i = 0; i < 3; ++i) {
        const T cell = i == axis ? steepAxisCell(s, k, p, outward, axis, m.checkerInvSize)
                                 : std::floor((&p.x)[i] * m.checkerInvSize);
        odd = odd != isOdd(cell);
    }
    return odd ? m.checkerColor : m.diffuse;
}

// x^n per lane for whole exponents n >= 0, by squaring as powInt() does.
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
    Vec3x<T> centre, diffuse;
    V specular{}, reflectivity{}, transparency{}, ior{};
    Mask lit{}, checker{};
    Mask shininessInt{};  // the whole shininess, or -1 for lanes that need std::pow
    V shininess{};
};

template <typename T>
LaneMaterials<T> gatherMaterials(const PreparedScene<T>& s, const typename Simd<T>::type& kHit,
                                 unsigned lanes) {
    using Lane = typename RayPacket<T>::MaskLane;
    LaneMaterials<T> g;
    for (unsigned bits = lanes; bits; bits &= bits - 1) {
        const int l = __builtin_ctz(bits);
        const int k = static_cast<int>(kHit[l]);
        const PreparedMaterial<T>& m = s.materials[s.material[k]];
        g.centre.setLane(l, s.centre[k]);
        g.diffuse.setLane(l, m.diffuse);
        g.specular[l] = m.specular;
        g.reflectivity[l] = m.reflectivity;
        g.transparency[l] = m.transparency;
        g.ior[l] = m.ior;
        g.lit[l] = m.lit ? Lane(-1) : Lane(0);
        g.checker[l] = m.checkerInvSize != T(0) ? Lane(-1) : Lane(0);
        g.shininessInt[l] = m.integerShininess;
        g.shininess[l] = m.shininess;
    }
    return g;
}

// Radiance along every ray of a packet at the given depth: the Whitted sum of
// SPEC §3, computed for all lanes at once, with the shadow, reflected and
// refracted rays of all lanes traced as packets.
template <typename T>
void tracePacket(const PreparedScene<T>& s, const RayPacket<T>& rays, int depth, Vec3x<T>& radiance,
                 RayCounts& counts) {
    using V = typename Simd<T>::type;
    V tHit, kHit;
    packetClosestHits(s.blocks, rays, tHit, kHit);
    radiance = Vec3x<T>::broadcast(s.background);
    const auto hit = (kHit >= T(0)) & maskFromBits<T>(rays.active);
    const unsigned lanes = laneBits(hit);
    if (!lanes) return;

    const LaneMaterials<T> g = gatherMaterials(s, kHit, lanes);
    const Vec3x<T> d = rays.dirs();
    const Vec3x<T> p = rays.origins() + tHit * d;
    // Normalised, not divided by the radius: p is off the surface by its
    // rounding error, and a normal that is not unit length makes reflect()
    // lengthen the ray, which puts the next hit further off; inside glass that
    // error grew sevenfold per internal reflection until float renders showed
    // speckles.
    const Vec3x<T> outward = normalize(p - g.centre);
    const auto inside = dot(d, outward) > T(0);  // the ray hit the surface from within
    const Vec3x<T> n = select(inside, -outward, outward);
    Vec3x<T> kd = g.diffuse;
    for (unsigned bits = laneBits(g.checker) & lanes; bits; bits &= bits - 1) {
        const int l = __builtin_ctz(bits);
        const int k = static_cast<int>(kHit[l]);
        kd.setLane(l, diffuseAt(s, k, s.materials[s.material[k]], p.lane(l), outward.lane(l)));
    }
    radiance = select(hit, Vec3x<T>::broadcast(s.ambient) * kd, radiance);

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
        RayPacket<T> shadow;
        shadow.assign(p, l, kHit, dot(l, outward) < T(0), litLanes);
        const V sj = packetTransmittance(s.blocks, s.transparency, shadow, distance, litLanes);
        const auto shaded = lit & (sj != T(0));
        if (!laneBits(shaded)) continue;
        Vec3x<T> term = kd * nl;
        const auto glossy = shaded & (g.specular > T(0));
        if (laneBits(glossy)) {
            const V nh = dot(n, normalize(l - d));
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
    if (depth >= s.maxDepth) return;

    // Refraction first, then reflection, each added in the order of the formula.
    V reflectWeight = g.reflectivity;
    const auto glass = hit & (g.transparency > T(0));
    if (laneBits(glass)) {
        const V eta = inside ? g.ior : T(1) / g.ior;
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
            RayPacket<T> refracted;
            refracted.assign(p, t, kHit, ~inside, bits);
            counts.refraction += __builtin_popcount(bits);
            Vec3x<T> sub;
            tracePacket(s, refracted, depth + 1, sub, counts);
            radiance = select(passes, radiance + g.transparency * sub, radiance);
        }
    }
    const auto mirror = hit & (reflectWeight > T(0));
    if (const unsigned bits = laneBits(mirror)) {
        const Vec3x<T> r = d - (T(2) * dot(d, n)) * n;  // reflect(d, n)
        RayPacket<T> reflected;
        reflected.assign(p, r, kHit, inside, bits);
        counts.reflection += __builtin_popcount(bits);
        Vec3x<T> sub;
        tracePacket(s, reflected, depth + 1, sub, counts);
        radiance = select(mirror, radiance + reflectWeight * sub, radiance);
    }
}

}  // namespace

template <typename T>
Vec<T> traceRay(const PreparedScene<T>& s, const Ray<T>& ray, int depth, RayCounts& counts) {
    RayPacket<T> packet;
    packet.set(0, ray.origin, ray.dir, ray.originSphere, ray.intoOrigin);
    packet.fromCamera = ray.fromCamera;
    Vec3x<T> radiance;
    tracePacket(s, packet, depth, radiance, counts);
    return radiance.lane(0);
}

template <typename T>
void traceCameraSamples(const PreparedScene<T>& s, const CameraSample<T>* samples, int count,
                        Vec<T>* radiance, RayCounts& counts) {
    constexpr int W = RayPacket<T>::kWidth;
    for (int first = 0; first < count; first += W) {
        const int m = std::min(W, count - first);
        // cameraDirection() for every lane at once, operation for operation.
        using V = typename Simd<T>::type;
        V x{}, y{};
        for (int l = 0; l < m; ++l) {
            const CameraSample<T>& cs = samples[first + l];
            x[l] = T(cs.i) + cs.u;
            y[l] = T(cs.j) + cs.v;
        }
        const CameraBasis<T>& cam = s.camera;
        x = (x / T(cam.width) * T(2) - T(1)) * cam.tanHalfFov * cam.aspect;
        y = (T(1) - y / T(cam.height) * T(2)) * cam.tanHalfFov;
        const Vec3x<T> dir =
            normalize(Vec3x<T>::broadcast(cam.forward) + x * Vec3x<T>::broadcast(cam.right) +
                      y * Vec3x<T>::broadcast(cam.up));
        RayPacket<T> packet;
        packet.fromCamera = true;
        packet.assign(Vec3x<T>::broadcast(cam.origin), dir, V{} - T(1),
                      typename RayPacket<T>::Mask{}, (1u << m) - 1);
        counts.camera += m;
        Vec3x<T> out;
        tracePacket(s, packet, 0, out, counts);
        for (int l = 0; l < m; ++l) radiance[first + l] = out.lane(l);
    }
}

template <typename T>
Vec<T> tracePixelSample(const PreparedScene<T>& s, int i, int j, T u, T v, RayCounts& counts) {
    const CameraSample<T> sample{i, j, u, v};
    Vec<T> radiance;
    traceCameraSamples(s, &sample, 1, &radiance, counts);
    return radiance;
}

template <typename T>
CameraSample<T> pixelSample(const PreparedScene<T>& s, int i, int j, int n) {
    if (s.samplesPerPixel == 1) return {i, j, T(0.5), T(0.5)};
    const SubPixel sp = subPixelSample(n, s.samplesPerPixel, pixelSeed(i, j));
    return {i, j, T(sp.u), T(sp.v)};
}

#define WHITTED_INSTANTIATE(T)                                                                \
    template PreparedScene<T> prepareScene<T>(const Scene&);                                  \
    template std::optional<Hit<T>> closestHit<T>(const PreparedScene<T>&, const Ray<T>&, T);  \
    template Vec<T> traceRay<T>(const PreparedScene<T>&, const Ray<T>&, int, RayCounts&);     \
    template void traceCameraSamples<T>(const PreparedScene<T>&, const CameraSample<T>*, int, \
                                        Vec<T>*, RayCounts&);                                 \
    template Vec<T> tracePixelSample<T>(const PreparedScene<T>&, int, int, T, T, RayCounts&); \
    template CameraSample<T> pixelSample<T>(const PreparedScene<T>&, int, int, int);
WHITTED_INSTANTIATE(float)
WHITTED_INSTANTIATE(double)
#undef WHITTED_INSTANTIATE

}  // namespace whitted
