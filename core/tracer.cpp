#include "tracer.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

// S_j: the product of the transparencies of every sphere between p and the light.
template <typename T>
T shadowTransmittance(const PreparedScene<T>& s, const Ray<T>& ray, T distance) {
    constexpr int W = SphereBlock<T>::kWidth;
    T transmittance = 1;
    const int blocks = static_cast<int>(s.blocks.blocks.size());
    for (int bi = 0; bi < blocks; ++bi) {
        const BlockRoots<T> r =
            intersectBlock(s.blocks.blocks[bi], ray.origin, ray.dir, false, lanesToTest(bi, ray));
        for (unsigned bits = r.valid; bits; bits &= bits - 1) {
            const int l = __builtin_ctz(bits);
            const int k = bi * W + l;
            const T tNear = r.tNear[l], tFar = r.tFar[l];
            const bool crosses = k == ray.originSphere ? tFar < distance
                                                       : (tNear > T(0) && tNear < distance) ||
                                                             (tFar > T(0) && tFar < distance);
            if (!crosses) continue;
            transmittance *= s.materials[s.material[k]].transparency;
            if (transmittance == T(0)) return transmittance;
        }
    }
    return transmittance;
}

template <typename T>
Vec<T> shade(const PreparedScene<T>& s, const Ray<T>& ray, const Hit<T>& hit, int depth,
             RayCounts& counts) {
    const int k = hit.sphere;
    const PreparedMaterial<T>& m = s.materials[s.material[k]];
    const Vec<T> p = ray.origin + hit.t * ray.dir;
    // Normalised, not divided by the radius: p is off the surface by its rounding
    // error, and a normal that is not unit length makes reflect() lengthen the
    // ray, which puts the next hit further off; inside glass that error grew
    // sevenfold per internal reflection until float renders showed speckles.
    const Vec<T> outward = glm::normalize(p - s.centre[k]);
    // The ray is inside the sphere when it hits the surface from within.
    const bool inside = dot3(ray.dir, outward) > T(0);
    const Vec<T> n = inside ? -outward : outward;
    const Vec<T> kd = diffuseAt(s, k, m, p, outward);

    Vec<T> colour = s.ambient * kd;
    if (m.lit) {
        for (const PreparedLight<T>& light : s.lights) {
            Vec<T> l = light.position - p;
            const T distance = std::sqrt(dot3(l, l));
            if (!(distance > T(0))) continue;
            l *= T(1) / distance;
            const T nl = dot3(n, l);
            if (nl <= T(0)) continue;
            ++counts.shadow;
            // The shadow ray goes into the sphere when it leaves p against the outward normal.
            const Ray<T> shadowRay{p, l, k, dot3(l, outward) < T(0)};
            const T sj = shadowTransmittance(s, shadowRay, distance);
            if (sj == T(0)) continue;
            Vec<T> term = kd * nl;
            if (m.specular > T(0)) {
                const Vec<T> h = glm::normalize(l - ray.dir);
                const T nh = dot3(n, h);
                if (nh > T(0)) {
                    const T spec = m.integerShininess >= 0 ? powInt(nh, m.integerShininess)
                                                           : std::pow(nh, m.shininess);
                    term += Vec<T>(m.specular * spec);
                }
            }
            colour += sj * light.color * term;
        }
    }

    if (depth >= s.maxDepth) return colour;
    T reflectWeight = m.reflectivity;
    if (m.transparency > T(0)) {
        const T eta = inside ? m.ior : T(1) / m.ior;
        if (auto t = refract(ray.dir, n, eta)) {
            ++counts.refraction;
            // Refracted rays cross the surface: into the sphere from outside, out of it from
            // inside.
            const Ray<T> refracted{p, *t, k, !inside};
            colour += m.transparency * traceRay(s, refracted, depth + 1, counts);
        } else {
            // Total internal reflection: the refracted share follows the reflected ray,
            // which is traced once for both shares.
            reflectWeight += m.transparency;
        }
    }
    if (reflectWeight > T(0)) {
        ++counts.reflection;
        const Ray<T> reflected{p, reflect(ray.dir, n), k, inside};
        colour += reflectWeight * traceRay(s, reflected, depth + 1, counts);
    }
    return colour;
}

}  // namespace

template <typename T>
Vec<T> traceRay(const PreparedScene<T>& s, const Ray<T>& ray, int depth, RayCounts& counts) {
    const auto hit = closestHit(s, ray);
    if (!hit) return s.background;
    return shade(s, ray, *hit, depth, counts);
}

namespace {

// Nearest hits of up to one packet of camera rays. Camera rays share their
// origin, so the offsets f = o - centre, |f|^2 and c are per sphere, not per ray,
// and the packet runs over rays instead of spheres. Each lane performs the
// operations of intersectBlock() for that sphere in the same order, so a
// camera ray finds the same hit here as through closestHit().
template <typename T>
void cameraHits(const PreparedScene<T>& s, const Vec<T>* dirs, int count, T* tHit, int* kHit) {
    using V = typename Simd<T>::type;
    constexpr int W = SphereBlock<T>::kWidth;
    V dx{}, dy{}, dz{};
    for (int l = 0; l < count; ++l) {
        dx[l] = dirs[l].x;
        dy[l] = dirs[l].y;
        dz[l] = dirs[l].z;
    }
    V bestT = V{} + std::numeric_limits<T>::infinity();
    V bestK = V{} - T(1);  // sphere index as T: exact for any realistic count
    const Vec<T>& o = s.camera.origin;
    const int n = s.blocks.count;
    for (int k = 0; k < n; ++k) {
        const SphereBlock<T>& blk = s.blocks.blocks[k / W];
        const int lane = k % W;
        const T fx = o.x - blk.cx[lane], fy = o.y - blk.cy[lane], fz = o.z - blk.cz[lane];
        const T ff = fx * fx + fy * fy + fz * fz;
        const T c = blk.cameraC[lane];
        const T rrHi = blk.rrHi[lane];
        const bool outside = c > ff * (T(16) * std::numeric_limits<T>::epsilon());
        const bool nearSurface = c < ff * T(0.0625) && c > -(ff * T(0.0625));
        const V b = fx * dx + fy * dy + fz * dz;
        V disc;
        if (nearSurface) {
            disc = b * b - c;
        } else {
            const V px = fx - b * dx, py = fy - b * dy, pz = fz - b * dz;
            disc = rrHi - (px * px + py * py + pz * pz);
        }
        auto hit = disc >= T(0);
        if (outside) hit &= ~(b > T(0));
        if (!laneBits(hit)) continue;
        const V root = laneSqrt(hit ? disc : V{});
        const V q = -b - (b < T(0) ? -root : root);
        const auto zero = q == T(0);
        const V t0 = zero ? V{} : c / (zero ? V{} + T(1) : q);
        const V t1 = zero ? V{} : q;
        const auto ordered = t0 < t1;
        const V tNear = ordered ? t0 : t1, tFar = ordered ? t1 : t0;
        const V t = tNear > T(0) ? tNear : tFar;
        const auto better = hit & (t > T(0)) & (t < bestT);
        bestT = better ? t : bestT;
        bestK = better ? V{} + T(k) : bestK;
    }
    for (int l = 0; l < count; ++l) {
        tHit[l] = bestT[l];
        kHit[l] = static_cast<int>(bestK[l]);
    }
}

}  // namespace

template <typename T>
void traceCameraSamples(const PreparedScene<T>& s, const CameraSample<T>* samples, int count,
                        Vec<T>* radiance, RayCounts& counts) {
    constexpr int W = SphereBlock<T>::kWidth;
    for (int first = 0; first < count; first += W) {
        const int m = std::min(W, count - first);
        Vec<T> dirs[W];
        T t[W];
        int k[W];
        for (int l = 0; l < m; ++l) {
            const CameraSample<T>& cs = samples[first + l];
            dirs[l] = cameraDirection(s.camera, cs.i, cs.j, cs.u, cs.v);
        }
        cameraHits(s, dirs, m, t, k);
        counts.camera += m;
        for (int l = 0; l < m; ++l) {
            const Ray<T> ray{s.camera.origin, dirs[l], -1, false, true};
            radiance[first + l] =
                k[l] < 0 ? s.background : shade(s, ray, Hit<T>{t[l], k[l]}, 0, counts);
        }
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
