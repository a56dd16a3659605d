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
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    const Vec<T>& c = s.centre[k];
    const T da = p[a] - c[a], db = p[b] - c[b];
    const T across = da * da + db * db;
    const T rest = (s.rrHi[k] - across) + s.rrLo[k];
    const T drop = across / (s.radius[k] + (rest > T(0) ? std::sqrt(rest) : T(0)));
    const T sign = outward[axis] >= T(0) ? T(1) : T(-1);
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
    if (std::fabs(outward.z) > std::fabs(outward[axis])) axis = 2;
    bool odd = false;
    for (int i = 0; i < 3; ++i) {
        const T cell = i == axis ? steepAxisCell(s, k, p, outward, axis, m.checkerInvSize)
                                 : std::floor(p[i] * m.checkerInvSize);
        odd = odd != isOdd(cell);
    }
    return odd ? m.checkerColor : m.diffuse;
}

// What shading needs to know about one lane's hit.
template <typename T>
struct SurfaceHit {
    Vec<T> p;        // hit point
    Vec<T> outward;  // unit outward normal
    Vec<T> n;        // unit normal facing the incoming ray
    Vec<T> kd;       // diffuse colour at p
    const PreparedMaterial<T>* m;
    int sphere;
    bool inside;  // the ray hit the surface from within
};

// Adds every light's diffuse and specular term to `radiance`, with one packet of
// shadow rays per light.
template <typename T>
void addLights(const PreparedScene<T>& s, const RayPacket<T>& rays, const SurfaceHit<T>* hit,
               unsigned lanes, Vec<T>* radiance, RayCounts& counts) {
    using V = typename Simd<T>::type;
    constexpr int W = RayPacket<T>::kWidth;
    for (const PreparedLight<T>& light : s.lights) {
        RayPacket<T> shadow;
        shadow.count = rays.count;
        V distance{}, nl{};
        unsigned active = 0;
        for (unsigned bits = lanes; bits; bits &= bits - 1) {
            const int l = __builtin_ctz(bits);
            const SurfaceHit<T>& h = hit[l];
            if (!h.m->lit) continue;
            Vec<T> dir = light.position - h.p;
            const T d = std::sqrt(dot3(dir, dir));
            if (!(d > T(0))) continue;
            dir *= T(1) / d;
            const T cosine = dot3(h.n, dir);
            if (cosine <= T(0)) continue;
            // The shadow ray goes into the sphere when it leaves p against the outward normal.
            shadow.set(l, h.p, dir, h.sphere, dot3(dir, h.outward) < T(0));
            distance[l] = d;
            nl[l] = cosine;
            active |= 1u << l;
        }
        if (!active) continue;
        counts.shadow += __builtin_popcount(active);
        const V sj = packetTransmittance(s.blocks, s.transparency, shadow, distance, active);
        for (unsigned bits = active; bits; bits &= bits - 1) {
            const int l = __builtin_ctz(bits);
            if (sj[l] == T(0)) continue;
            const SurfaceHit<T>& h = hit[l];
            Vec<T> term = h.kd * nl[l];
            if (h.m->specular > T(0)) {
                const Vec<T> half = glm::normalize(shadow.dir(l) - rays.dir(l));
                const T nh = dot3(h.n, half);
                if (nh > T(0)) {
                    const T spec = h.m->integerShininess >= 0 ? powInt(nh, h.m->integerShininess)
                                                              : std::pow(nh, h.m->shininess);
                    term += Vec<T>(h.m->specular * spec);
                }
            }
            radiance[l] += sj[l] * light.color * term;
        }
    }
    (void)W;
}

// Radiance along every ray of a packet at the given depth: the Whitted sum of
// SPEC §3 per lane, with the secondary rays of all lanes traced as packets.
template <typename T>
void tracePacket(const PreparedScene<T>& s, const RayPacket<T>& rays, int depth, Vec<T>* radiance,
                 RayCounts& counts) {
    using V = typename Simd<T>::type;
    constexpr int W = RayPacket<T>::kWidth;
    V tHit, kHit;
    packetClosestHits(s.blocks, rays, tHit, kHit);

    SurfaceHit<T> hit[W];
    unsigned lanes = 0;
    for (int l = 0; l < rays.count; ++l) {
        if (kHit[l] < T(0)) {
            radiance[l] = s.background;
            continue;
        }
        SurfaceHit<T>& h = hit[l];
        h.sphere = static_cast<int>(kHit[l]);
        h.m = &s.materials[s.material[h.sphere]];
        const Vec<T> d = rays.dir(l);
        h.p = rays.origin(l) + tHit[l] * d;
        // Normalised, not divided by the radius: p is off the surface by its
        // rounding error, and a normal that is not unit length makes reflect()
        // lengthen the ray, which puts the next hit further off; inside glass
        // that error grew sevenfold per internal reflection until float
        // renders showed speckles.
        h.outward = glm::normalize(h.p - s.centre[h.sphere]);
        h.inside = dot3(d, h.outward) > T(0);
        h.n = h.inside ? -h.outward : h.outward;
        h.kd = diffuseAt(s, h.sphere, *h.m, h.p, h.outward);
        radiance[l] = s.ambient * h.kd;
        lanes |= 1u << l;
    }
    if (!lanes) return;
    if (!s.lights.empty()) addLights(s, rays, hit, lanes, radiance, counts);
    if (depth >= s.maxDepth) return;

    // Refraction first, then reflection, each lane adding in the order of the formula.
    RayPacket<T> refracted, reflected;
    int refractedLane[W], reflectedLane[W];
    T reflectWeight[W];
    for (unsigned bits = lanes; bits; bits &= bits - 1) {
        const int l = __builtin_ctz(bits);
        const SurfaceHit<T>& h = hit[l];
        const Vec<T> d = rays.dir(l);
        reflectWeight[l] = h.m->reflectivity;
        if (h.m->transparency > T(0)) {
            const T eta = h.inside ? h.m->ior : T(1) / h.m->ior;
            if (auto t = refract(d, h.n, eta)) {
                // Refracted rays cross the surface: into the sphere from outside, out from inside.
                refractedLane[refracted.count] = l;
                refracted.set(refracted.count++, h.p, *t, h.sphere, !h.inside);
            } else {
                // Total internal reflection: the refracted share follows the reflected
                // ray, which is traced once for both shares.
                reflectWeight[l] += h.m->transparency;
            }
        }
        if (reflectWeight[l] > T(0)) {
            reflectedLane[reflected.count] = l;
            reflected.set(reflected.count++, h.p, reflect(d, h.n), h.sphere, h.inside);
        }
    }
    Vec<T> sub[W];
    if (refracted.count) {
        counts.refraction += refracted.count;
        tracePacket(s, refracted, depth + 1, sub, counts);
        for (int i = 0; i < refracted.count; ++i) {
            const int l = refractedLane[i];
            radiance[l] += hit[l].m->transparency * sub[i];
        }
    }
    if (reflected.count) {
        counts.reflection += reflected.count;
        tracePacket(s, reflected, depth + 1, sub, counts);
        for (int i = 0; i < reflected.count; ++i) {
            const int l = reflectedLane[i];
            radiance[l] += reflectWeight[l] * sub[i];
        }
    }
}

}  // namespace

template <typename T>
Vec<T> traceRay(const PreparedScene<T>& s, const Ray<T>& ray, int depth, RayCounts& counts) {
    RayPacket<T> packet;
    packet.count = 1;
    packet.set(0, ray.origin, ray.dir, ray.originSphere, ray.intoOrigin);
    packet.fromCamera = ray.fromCamera;
    Vec<T> radiance;
    tracePacket(s, packet, depth, &radiance, counts);
    return radiance;
}

template <typename T>
void traceCameraSamples(const PreparedScene<T>& s, const CameraSample<T>* samples, int count,
                        Vec<T>* radiance, RayCounts& counts) {
    constexpr int W = RayPacket<T>::kWidth;
    for (int first = 0; first < count; first += W) {
        RayPacket<T> packet;
        packet.count = std::min(W, count - first);
        packet.fromCamera = true;
        for (int l = 0; l < packet.count; ++l) {
            const CameraSample<T>& cs = samples[first + l];
            packet.set(l, s.camera.origin, cameraDirection(s.camera, cs.i, cs.j, cs.u, cs.v), -1,
                       false);
        }
        counts.camera += packet.count;
        tracePacket(s, packet, 0, radiance + first, counts);
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
