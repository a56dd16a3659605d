// Shared by the numerics property tests (tests/core/test_numerics_*.cpp):
// seeds that print and replay, random scenes, a quad-precision reference for
// ray against sphere, and the tracer's shadow query for one ray.
//
// Only the tracer's public interface is used (Scene, prepareScene, closestHit,
// traceRay, packetTransmittance, render), so these tests survive a rewrite of
// the intersection code. Prepared positions are converted to world positions
// through PreparedScene::frameOrigin (world = frameOrigin + prepared), never
// assumed to be world positions.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "support/core_support.h"
#include "tracer/ray_packet.h"
#include "tracer/renderer.h"
#include "tracer/tracer.h"

namespace whitted::test {

// The band of the intersection properties: a hit (or a miss) within
// delta = K eps (|o - c| + r) of the exact answer is right, with K = kBand.
constexpr double kBand = 16;
// Random spheres a property is checked on, each with its own rays.
constexpr int kSpheres = 2000;

// ---- seeds --------------------------------------------------------------------

// The seed of a property test: WHITTED_TEST_SEED (decimal or 0x...) when set, else a
// fixed default derived from the test's name, so that CI runs repeat. Printed on
// stdout and recorded in the XML report, so a failure can be replayed with
//   WHITTED_TEST_SEED=<seed> test_numerics_... --gtest_filter=<suite>.<test>
inline std::uint64_t propertySeed() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string name =
        info ? std::string(info->test_suite_name()) + "." + info->name() : std::string("?");
    std::uint64_t seed = 1469598103934665603ull;  // FNV-1a of the test name
    for (const char c : name) seed = (seed ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    seed &= 0xffffffffull;  // short enough to type
    if (const char* env = std::getenv("WHITTED_TEST_SEED"); env && *env)
        seed = std::strtoull(env, nullptr, 0);
    std::cout << "[   SEED   ] " << name << ": WHITTED_TEST_SEED=" << seed << std::endl;
    ::testing::Test::RecordProperty("seed", std::to_string(seed));
    return seed;
}

using Rng = std::mt19937_64;

inline double uniform(Rng& rng, double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// 10^U(log10 lo, log10 hi): every decade equally likely.
inline double logUniform(Rng& rng, double lo, double hi) {
    return std::pow(10.0, uniform(rng, std::log10(lo), std::log10(hi)));
}

inline Vec3 randomUnit(Rng& rng) {
    std::normal_distribution<double> g;
    for (;;) {
        const Vec3 v{g(rng), g(rng), g(rng)};
        const double l = glm::length(v);
        if (l > 1e-3) return v / l;
    }
}

// A unit vector perpendicular to unit n (finite), uniformly around it.
inline Vec3 randomPerpendicular(Rng& rng, const Vec3& n) {
    if (!std::isfinite(glm::dot(n, n))) return Vec3(std::nan(""));
    for (;;) {
        const Vec3 v = randomUnit(rng);
        const Vec3 p = v - glm::dot(v, n) * n;
        const double l = glm::length(p);
        if (l > 1e-3) return p / l;
    }
}

// ---- scenes -------------------------------------------------------------------

// A 1x1 image of one opaque sphere seen from `cam`, looking at its centre, the
// camera's up random but never within ~6 degrees of the view direction.
inline Scene oneSphereScene(Rng& rng, const Vec3& cam, const Vec3& centre, double radius,
                            Precision precision) {
    const Vec3 w = glm::normalize(centre - cam);
    Scene scene;
    scene.camera.position = cam;
    scene.camera.lookAt = centre;
    Vec3 up = randomUnit(rng);
    while (glm::length(glm::cross(up, w)) < 0.1) up = randomUnit(rng);
    scene.camera.up = up;
    scene.render.width = scene.render.height = 1;
    scene.render.precision = precision;
    scene.materials = {makeMaterial("m", {0.8, 0.8, 0.8})};  // opaque
    scene.spheres = {makeSphere("s", centre, radius, "m")};
    return scene;
}

template <typename T>
constexpr Precision precisionOf() {
    return sizeof(T) == sizeof(float) ? Precision::Float : Precision::Double;
}

template <typename T>
constexpr const char* precisionLabel() {
    return sizeof(T) == sizeof(float) ? "float" : "double";
}

inline std::string label(Precision p) {
    return std::string(precisionName(p));
}

// World position of a prepared-frame point.
template <typename T>
Vec3 toWorld(const PreparedScene<T>& s, const Vec<T>& p) {
    return s.frameOrigin + Vec3(p);
}

// S_j of SPEC §3 for one shadow ray, through the tracer's packet code with one
// lane, as tracer.cpp forms shadow rays: from p (on sphere k) towards the light,
// going into sphere k when it leaves p against the outward normal.
template <typename T>
T shadowTransmittance(const PreparedScene<T>& s, const Vec<T>& p, int k, const Vec<T>& light) {
    Vec<T> l = light - p;
    const T distance = std::sqrt(l.x * l.x + l.y * l.y + l.z * l.z);
    l = l * (T(1) / distance);
    const Vec<T> outward = glm::normalize(p - s.spheres.centre[k]);
    const bool into = glm::dot(l, outward) < T(0);
    RayPacket<T> packet;
    packet.set(0, p, l, k, into);
    using V = typename Simd<T>::type;
    const V d = V{} + distance;
    return packetTransmittance(s.spheres, s.transparency, packet, d, packet.active)[0];
}

// ---- quad-precision reference -------------------------------------------------

using Quad = __float128;

inline Quad qsqrt(Quad v) {
    if (!(v > 0)) return 0;
    Quad x = std::sqrt(static_cast<long double>(v));  // 64 bits; Newton doubles them
    for (int i = 0; i < 2; ++i) x = (x + v / x) / 2;
    return x;
}
inline Quad qabs(Quad v) {
    return v < 0 ? -v : v;
}

struct QVec {
    Quad x = 0, y = 0, z = 0;
    QVec() = default;
    QVec(Quad a, Quad b, Quad c) : x(a), y(b), z(c) {}
    explicit QVec(const glm::dvec3& v) : x(v.x), y(v.y), z(v.z) {}
    explicit QVec(const glm::vec3& v) : x(v.x), y(v.y), z(v.z) {}
};
inline QVec operator+(const QVec& a, const QVec& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline QVec operator-(const QVec& a, const QVec& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline QVec operator*(Quad s, const QVec& a) {
    return {s * a.x, s * a.y, s * a.z};
}
inline Quad dot(const QVec& a, const QVec& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Quad length(const QVec& a) {
    return qsqrt(dot(a, a));
}

// The line o + t d (d as given, not necessarily unit length) against a sphere,
// exact to far below double precision: the discriminant from the perpendicular
// distance h, the near root as C/q so neither root cancels.
struct ReferenceHit {
    bool hit = false;
    Quad tNear = 0, tFar = 0;
    Quad h = 0;          // distance from the centre to the line
    Quad tClosest = 0;   // parameter of the line's point nearest the centre
    Quad halfChord = 0;  // sqrt(r^2 - h^2), a length; 0 on a miss
};

inline ReferenceHit referenceIntersect(const QVec& o, const QVec& d, const QVec& c, Quad r) {
    ReferenceHit ref;
    const QVec f = o - c;
    const Quad a = dot(d, d), b = dot(f, d);
    const QVec perp = f - (b / a) * d;
    ref.h = length(perp);
    ref.tClosest = -b / a;
    const Quad disc = r * r - dot(perp, perp);
    if (disc < 0) return ref;
    ref.hit = true;
    ref.halfChord = qsqrt(disc);
    const Quad root = qsqrt(a) * ref.halfChord;  // sqrt(b^2 - a C)
    const Quad q = -b + (b < 0 ? root : -root);
    const Quad cc = dot(f, f) - r * r;
    const Quad t0 = q != 0 ? cc / q : 0, t1 = q / a;
    ref.tNear = t0 < t1 ? t0 : t1;
    ref.tFar = t0 < t1 ? t1 : t0;
    return ref;
}

inline std::string str(Quad v) {
    std::ostringstream s;
    s.precision(17);
    s << static_cast<double>(v);
    return s.str();
}

inline std::string str(const Vec3& v) {
    std::ostringstream s;
    s.precision(17);
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}

// The largest value seen so far and a description of where.
struct Worst {
    double value = 0;
    std::string where = "none";
    void note(double v, const std::string& w) {
        if (v > value) {
            value = v;
            where = w;
        }
    }
};

}  // namespace whitted::test
