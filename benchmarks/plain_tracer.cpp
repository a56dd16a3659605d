#include "plain_tracer.h"

#include <atomic>
#include <cmath>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace whitted::bench {
namespace {

template <typename T>
using V3 = glm::vec<3, T>;

template <typename T>
struct PlainScene {
    struct Ball {
        V3<T> c;
        T r;
        int m;
    };
    struct Mat {
        V3<T> kd, checker;
        T size, ks, n, kr, kt, ior;
    };
    std::vector<Ball> balls;
    std::vector<Mat> mats;
    std::vector<std::pair<V3<T>, V3<T>>> lights;  // position, colour
    V3<T> background, ambient, eye, forward, right, up;
    T tanHalf, aspect;
    int width, height, maxDepth;
};

template <typename T>
bool hitBall(const typename PlainScene<T>::Ball& b, const V3<T>& o, const V3<T>& d, T& t) {
    const V3<T> oc = o - b.c;
    const T bb = T(2) * glm::dot(oc, d);
    const T c = glm::dot(oc, oc) - b.r * b.r;
    const T disc = bb * bb - T(4) * c;
    if (disc < 0) return false;
    const T sq = std::sqrt(disc);
    t = (-bb - sq) / T(2);
    if (t < T(1e-4)) t = (-bb + sq) / T(2);
    return t >= T(1e-4);
}

template <typename T>
V3<T> trace(const PlainScene<T>& s, const V3<T>& o, const V3<T>& d, int depth,
            unsigned long long& rays) {
    ++rays;
    T best = std::numeric_limits<T>::max(), t;
    int hit = -1;
    for (size_t k = 0; k < s.balls.size(); ++k)
        if (hitBall<T>(s.balls[k], o, d, t) && t < best) best = t, hit = int(k);
    if (hit < 0) return s.background;
    const auto& ball = s.balls[hit];
    const auto& m = s.mats[ball.m];
    const V3<T> p = o + best * d;
    V3<T> n = glm::normalize(p - ball.c);
    const bool inside = glm::dot(d, n) > 0;
    if (inside) n = -n;
    V3<T> kd = m.kd;
    if (m.size > 0) {
        const long cell = long(std::floor(p.x / m.size)) + long(std::floor(p.y / m.size)) +
                          long(std::floor(p.z / m.size));
        if (cell & 1) kd = m.checker;
    }
    V3<T> colour = s.ambient * kd;
    const V3<T> lifted = p + n * T(1e-4);
    for (const auto& [lp, lc] : s.lights) {
        V3<T> l = lp - p;
        const T dist = glm::length(l);
        l /= dist;
        const T nl = glm::dot(n, l);
        if (nl <= 0) continue;
        ++rays;
        T transmit = 1;
        for (const auto& b : s.balls)
            if (hitBall<T>(b, lifted, l, t) && t < dist) transmit *= s.mats[b.m].kt;
        if (transmit == 0) continue;
        const T nh = std::max(T(0), glm::dot(n, glm::normalize(l - d)));
        colour += transmit * lc * (kd * nl + V3<T>(m.ks * std::pow(nh, m.n)));
    }
    if (depth >= s.maxDepth) return colour;
    if (m.kt > 0) {
        const T eta = inside ? m.ior : T(1) / m.ior;
        const T cosi = -glm::dot(d, n);
        const T k = 1 - eta * eta * (1 - cosi * cosi);
        if (k >= 0) {
            const V3<T> dir = glm::normalize(eta * d + (eta * cosi - std::sqrt(k)) * n);
            colour += m.kt * trace(s, p - n * T(1e-4), dir, depth + 1, rays);
        }
    }
    if (m.kr > 0) colour += m.kr * trace(s, lifted, glm::reflect(d, n), depth + 1, rays);
    return colour;
}

template <typename T>
PlainScene<T> convert(const Scene& scene) {
    PlainScene<T> s;
    for (const Material& m : scene.materials)
        s.mats.push_back({V3<T>(m.diffuse), V3<T>(m.checker ? m.checker->color : Vec3(0.0)),
                          T(m.checker ? m.checker->size : 0.0), T(m.specular), T(m.shininess),
                          T(m.reflectivity), T(m.transparency), T(m.ior)});
    for (const Sphere& b : scene.spheres)
        s.balls.push_back({V3<T>(b.center), T(b.radius), findMaterial(scene, b.material)});
    for (const Light& l : scene.lights)
        s.lights.push_back({V3<T>(l.position), V3<T>(l.color * l.intensity)});
    s.background = V3<T>(scene.background);
    s.ambient = V3<T>(scene.ambient);
    s.eye = V3<T>(scene.camera.position);
    s.forward = glm::normalize(V3<T>(scene.camera.lookAt) - s.eye);
    s.right = glm::normalize(glm::cross(V3<T>(scene.camera.up), s.forward));
    s.up = glm::cross(s.forward, s.right);
    s.tanHalf = T(std::tan(scene.camera.vfovDegrees * M_PI / 360.0));
    s.width = scene.render.width;
    s.height = scene.render.height;
    s.aspect = T(s.width) / T(s.height);
    s.maxDepth = scene.render.maxDepth;
    return s;
}

}  // namespace

template <typename T>
unsigned long long renderPlain(const Scene& scene, int threads, Image& out) {
    const PlainScene<T> s = convert<T>(scene);
    out = Image(s.width, s.height);
    std::atomic<int> nextRow{0};
    std::atomic<unsigned long long> total{0};
    auto worker = [&] {
        unsigned long long rays = 0;
        for (int j; (j = nextRow++) < s.height;)
            for (int i = 0; i < s.width; ++i) {
                const T x = ((T(i) + T(0.5)) / T(s.width) * 2 - 1) * s.tanHalf * s.aspect;
                const T y = (1 - (T(j) + T(0.5)) / T(s.height) * 2) * s.tanHalf;
                const V3<T> d = glm::normalize(s.forward + x * s.right + y * s.up);
                const V3<T> c = trace(s, s.eye, d, 0, rays);
                float* px = out.pixel(i, j);
                px[0] = float(c.x), px[1] = float(c.y), px[2] = float(c.z);
            }
        total += rays;
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
    return total;
}

template unsigned long long renderPlain<float>(const Scene&, int, Image&);
template unsigned long long renderPlain<double>(const Scene&, int, Image&);

}  // namespace whitted::bench
