#include "ray_decisions.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "ray_packet.h"

namespace whitted {

namespace {

// tracePacket() (tracer.cpp) for a single ray, recording its decisions instead of
// adding up radiance. Every expression is the tracer's, in the same order, so that
// each decision comes out as the tracer makes it, to the last bit.
template <typename T>
class DecisionWalk {
  public:
    DecisionWalk(const PreparedScene<T>& s, std::vector<Decision>& out) : s_(s), out_(out) {}

    void trace(const Ray<T>& ray, int depth) {
        const std::optional<Hit<T>> hit = closestHit(s_, ray);
        out_.push_back({DecisionKind::Hit, hit ? hit->sphere : -1});
        if (!hit) return;
        const int k = hit->sphere;
        const PreparedMaterial<T>& m = s_.materials[s_.material[k]];
        const Vec<T> d = ray.dir;
        const Vec<T> p = ray.origin + hit->t * d;
        const Vec<T> outward = glm::normalize(p - s_.spheres.centre[k]);
        const bool inside = glm::dot(d, outward) > T(0);
        const Vec<T> n = inside ? -outward : outward;
        for (const PreparedLight<T>& light : s_.lights)
            out_.push_back({DecisionKind::Shadow, shadowed(light, p, n, outward, k, m.lit)});
        if (depth >= s_.maxDepth) return;

        T reflectWeight = m.reflectivity;
        if (m.transparency > T(0)) {
            const T eta = inside ? m.ior : T(1) / m.ior;
            const T cosi = -glm::dot(d, n);
            const T root2 = T(1) - eta * eta * (T(1) - cosi * cosi);
            const bool tir = !(root2 >= T(0));
            out_.push_back({DecisionKind::Tir, tir ? 1 : 0});
            if (tir) {
                reflectWeight = reflectWeight + m.transparency;
            } else {
                const Vec<T> t = glm::normalize(eta * d + (eta * cosi - std::sqrt(root2)) * n);
                trace(Ray<T>{p, t, k, !inside, false}, depth + 1);
            }
        }
        if (reflectWeight > T(0)) {
            const Vec<T> r = d - (T(2) * glm::dot(d, n)) * n;
            trace(Ray<T>{p, r, k, inside, false}, depth + 1);
        }
    }

  private:
    // 1 when the light is tested and something on the way dims it (S_j < 1).
    int shadowed(const PreparedLight<T>& light, const Vec<T>& p, const Vec<T>& n,
                 const Vec<T>& outward, int sphere, bool lit) const {
        Vec<T> l = light.position - p;
        const T distance = std::sqrt(glm::dot(l, l));
        l = l * (T(1) / distance);
        const T nl = glm::dot(n, l);
        if (!(lit && distance > T(0) && nl > T(0))) return 0;
        // A one-lane packet, as closestHit() builds one: the tracer's own shadow test.
        RayPacket<T> shadow;
        shadow.set(0, p, l, sphere, glm::dot(l, outward) < T(0));
        const typename Simd<T>::type limit = typename Simd<T>::type{} + distance;
        const T sj = packetTransmittance(s_.spheres, s_.transparency, shadow, limit, 1u)[0];
        return sj < T(1) ? 1 : 0;
    }

    const PreparedScene<T>& s_;
    std::vector<Decision>& out_;
};

// One step of a 64-bit hash over a sequence: the running value is re-mixed at every
// element (splitmix64's finaliser), so order and length both matter.
std::uint64_t mix(std::uint64_t h, int value) {
    std::uint64_t x = h ^ (std::uint64_t(std::int64_t(value)) + 0x9e3779b97f4a7c15ull);
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ull;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebull;
    x ^= x >> 31;
    return x;
}

}  // namespace

template <typename T>
void pixelDecisions(const PreparedScene<T>& s, int i, int j, std::vector<Decision>& out) {
    out.clear();
    // The pixel centre, as the tracer's camera rows compute it for one sample per pixel.
    const Vec<T> dir = cameraDirection(s.camera, i, j, T(0.5), T(0.5));
    DecisionWalk<T>(s, out).trace(Ray<T>{s.camera.origin, dir, -1, false, true}, 0);
}

DecisionSignature signatureOf(const std::vector<Decision>& decisions) {
    DecisionSignature sig;
    for (const Decision& d : decisions) {
        std::uint64_t& h = d.kind == DecisionKind::Hit      ? sig.hits
                           : d.kind == DecisionKind::Shadow ? sig.shadows
                                                            : sig.tir;
        h = mix(h, d.value);
    }
    return sig;
}

DecisionDifference firstDifference(const std::vector<Decision>& a, const std::vector<Decision>& b) {
    const std::size_t n = std::min(a.size(), b.size());
    for (std::size_t i = 0; i < n; ++i) {
        if (a[i] == b[i]) continue;
        if (a[i].kind != b[i].kind) return DecisionDifference::Hit;
        switch (a[i].kind) {
            case DecisionKind::Hit:
                return DecisionDifference::Hit;
            case DecisionKind::Shadow:
                return DecisionDifference::Shadow;
            case DecisionKind::Tir:
                return DecisionDifference::Tir;
        }
    }
    return a.size() == b.size() ? DecisionDifference::None : DecisionDifference::Hit;
}

template void pixelDecisions<float>(const PreparedScene<float>&, int, int, std::vector<Decision>&);
template void pixelDecisions<double>(const PreparedScene<double>&, int, int,
                                     std::vector<Decision>&);

}  // namespace whitted
