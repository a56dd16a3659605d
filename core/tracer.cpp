#include "tracer.h"

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
        const bool diffuseLit = m.diffuse != Vec3(0.0) ||
                                (m.checker && m.checker->color != Vec3(0.0));
        pm.lit = diffuseLit || m.specular > 0;
        s.materials.push_back(pm);
    }
    for (const Light& l : scene.lights) {
        const Vec3 c = l.color * l.intensity;
        if (c == Vec3(0.0)) continue;  // a dark light adds nothing: no shadow rays for it
        s.lights.push_back({Vec<T>(l.position), Vec<T>(c)});
    }
    for (const Sphere& sp : scene.spheres) {
        T hi, lo;
        splitRadiusSquared(T(sp.radius), hi, lo);
        s.centre.push_back(Vec<T>(sp.center));
        s.radius.push_back(T(sp.radius));
        s.rrHi.push_back(hi);
        s.rrLo.push_back(lo);
        s.material.push_back(findMaterial(scene, sp.material));
        s.cameraOffsetSquared.push_back(
            accurateOffsetSquared(s.camera.origin, s.centre.back(), hi, lo));
    }
    return s;
}

template <typename T>
std::optional<Hit<T>> closestHit(const PreparedScene<T>& s, const Ray<T>& ray, T tMax) {
    std::optional<Hit<T>> best;
    const int n = static_cast<int>(s.centre.size());
    for (int k = 0; k < n; ++k) {
        const bool self = k == ray.originSphere;
        if (self && !ray.intoOrigin) continue;  // convex: leaving it, it cannot be hit again
        auto roots = intersectSphere(ray.origin, ray.dir, s.centre[k], s.rrHi[k], s.rrLo[k],
                                     ray.offsetSquared ? &(*ray.offsetSquared)[k] : nullptr);
        if (!roots) continue;
        T t = self ? roots->tFar : (roots->tNear > T(0) ? roots->tNear : roots->tFar);
        if (t > T(0) && t < tMax) {
            tMax = t;
            best = Hit<T>{t, k};
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
bool oddCell(T coordinate) {
    const T f = std::floor(coordinate);
    const T half = f * T(0.5);
    return half != std::floor(half);
}

template <typename T>
Vec<T> diffuseAt(const PreparedMaterial<T>& m, const Vec<T>& p) {
    if (m.checkerInvSize == T(0)) return m.diffuse;
    const bool odd = (oddCell(p.x * m.checkerInvSize) != oddCell(p.y * m.checkerInvSize)) !=
                     oddCell(p.z * m.checkerInvSize);
    return odd ? m.checkerColor : m.diffuse;
}

// S_j: the product of the transparencies of every sphere between p and the light.
template <typename T>
T shadowTransmittance(const PreparedScene<T>& s, const Ray<T>& ray, T distance) {
    T transmittance = 1;
    const int n = static_cast<int>(s.centre.size());
    for (int k = 0; k < n; ++k) {
        const bool self = k == ray.originSphere;
        if (self && !ray.intoOrigin) continue;
        auto roots = intersectSphere(ray.origin, ray.dir, s.centre[k], s.rrHi[k], s.rrLo[k]);
        if (!roots) continue;
        const bool crosses =
            self ? roots->tFar < distance
                 : (roots->tNear > T(0) && roots->tNear < distance) ||
                       (roots->tFar > T(0) && roots->tFar < distance);
        if (!crosses) continue;
        transmittance *= s.materials[s.material[k]].transparency;
        if (transmittance == T(0)) break;
    }
    return transmittance;
}

template <typename T>
Vec<T> shade(const PreparedScene<T>& s, const Ray<T>& ray, const Hit<T>& hit, int depth,
             RayCounts& counts) {
    const int k = hit.sphere;
    const PreparedMaterial<T>& m = s.materials[s.material[k]];
    const Vec<T> p = ray.origin + hit.t * ray.dir;
    const Vec<T> outward = (p - s.centre[k]) / s.radius[k];
    // The ray is inside the sphere when it hits the surface from within.
    const bool inside = dot3(ray.dir, outward) > T(0);
    const Vec<T> n = inside ? -outward : outward;
    const Vec<T> kd = diffuseAt(m, p);

    Vec<T> colour = s.ambient * kd;
    if (m.lit) {
        for (const PreparedLight<T>& light : s.lights) {
            Vec<T> l = light.position - p;
            const T distance = std::sqrt(dot3(l, l));
            if (!(distance > T(0))) continue;
            l /= distance;
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
            // Refracted rays cross the surface: into the sphere from outside, out of it from inside.
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

template <typename T>
Vec<T> tracePixelSample(const PreparedScene<T>& s, int i, int j, T u, T v, RayCounts& counts) {
    ++counts.camera;
    const Ray<T> ray{s.camera.origin, cameraDirection(s.camera, i, j, u, v), -1, false,
                     &s.cameraOffsetSquared};
    return traceRay(s, ray, 0, counts);
}

template <typename T>
void accumulatePixel(const PreparedScene<T>& s, int i, int j, int first, int last,
                     glm::dvec3& sum, RayCounts& counts) {
    const std::uint32_t seed = pixelSeed(i, j);
    for (int n = first; n < last; ++n) {
        const SubPixel sp = subPixelSample(n, s.samplesPerPixel, seed);
        sum += glm::dvec3(tracePixelSample(s, i, j, T(sp.u), T(sp.v), counts));
    }
}

#define WHITTED_INSTANTIATE(T)                                                                \
    template PreparedScene<T> prepareScene<T>(const Scene&);                                  \
    template std::optional<Hit<T>> closestHit<T>(const PreparedScene<T>&, const Ray<T>&, T);  \
    template Vec<T> traceRay<T>(const PreparedScene<T>&, const Ray<T>&, int, RayCounts&);     \
    template Vec<T> tracePixelSample<T>(const PreparedScene<T>&, int, int, T, T, RayCounts&); \
    template void accumulatePixel<T>(const PreparedScene<T>&, int, int, int, int,             \
                                     glm::dvec3&, RayCounts&);
WHITTED_INSTANTIATE(float)
WHITTED_INSTANTIATE(double)
#undef WHITTED_INSTANTIATE

}  // namespace whitted
