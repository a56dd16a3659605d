#include "embree_tracer.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "tracer/camera.h"

namespace whitted {

namespace {

using vec3 = glm::vec3;

// Where a secondary ray starts along itself: past the rounding of its origin on
// a ball of radius 0.05 to 0.3 within 100 units of the camera.
constexpr float kEmbreeRayOffset = 1e-4f;
// Spheres at least this large stay out of Embree (tested in double instead).
constexpr double kHugeRadius = 1000.0;

struct Mat {
    vec3 diffuse, checker;
    double checkerSize = 0;  // 0: no checker
    float ks, shininess, kr, kt, ior;
    bool lit;
};

struct Big {
    glm::dvec3 centre;
    double radius;
    int sphere;
};

struct Hit {
    float t;
    int sphere;
    double tDouble;  // exact enough for a huge sphere's point and checker
};

struct Shading {
    std::vector<vec3> centre;
    std::vector<int> material;  // per scene sphere
    std::vector<float> transparency;
    std::vector<int> sphereOfPrim;  // Embree primID -> scene sphere
    std::vector<Big> big;
    std::vector<int> bigOf;  // per scene sphere: its index in big, or -1
    std::vector<Mat> mats;
    std::vector<vec3> lightPos, lightColor;
    vec3 background, ambient;
    int maxDepth = 0;
    CameraBasis<float> camera;
};

// The context an occlusion filter sees (Embree passes our context pointer on).
struct ShadowContext {
    RTCIntersectContext context;
    const Shading* s;
    int origin;
    bool into;
    float transmittance;
    std::vector<unsigned>* seen;  // primitives already counted (each sphere once)
};

void shadowFilter(const RTCFilterFunctionNArguments* args) {
    auto* c = reinterpret_cast<ShadowContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (!args->valid[i]) continue;
        const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
        const int sphere = c->s->sphereOfPrim[prim];
        const bool counted = std::find(c->seen->begin(), c->seen->end(), prim) != c->seen->end();
        if ((sphere == c->origin && !c->into) || counted) {
            args->valid[i] = 0;
            continue;
        }
        c->seen->push_back(prim);
        const float kt = c->s->transparency[sphere];
        if (kt == 0.0f) {
            c->transmittance = 0.0f;  // accepted: the occlusion query stops here
        } else {
            c->transmittance *= kt;
            args->valid[i] = 0;
        }
    }
}

void check(RTCDevice device) {
    const RTCError e = rtcGetDeviceError(device);
    if (e != RTC_ERROR_NONE) throw std::runtime_error("Embree error " + std::to_string(int(e)));
}

// Both roots of a huge sphere in double; the near one first.
std::optional<std::pair<double, double>> bigRoots(const Big& b, const glm::dvec3& o,
                                                  const glm::dvec3& d) {
    const glm::dvec3 f = o - b.centre;
    const double half = glm::dot(f, d);
    const double len = std::sqrt(glm::dot(f, f));
    const double c = (len - b.radius) * (len + b.radius);
    const double disc = half * half - c;
    if (!(disc >= 0)) return std::nullopt;
    const double q = -half - std::copysign(std::sqrt(disc), half);
    const double r0 = q, r1 = c / q;
    return std::make_pair(std::min(r0, r1), std::max(r0, r1));
}

class Tracer {
  public:
    Tracer(const Shading& s, RTCScene scene, RayCounts& counts)
        : s_(s), scene_(scene), counts_(counts) {}

    void row(int y, vec3* out) {
        const int width = s_.camera.width;
        for (int x0 = 0; x0 < width; x0 += 16) packet(x0, y, std::min(16, width - x0), out + x0);
    }

  private:
    void packet(int x0, int y, int lanes, vec3* out) {
        alignas(64) int valid[16];
        alignas(64) RTCRayHit16 rh;
        const vec3 o = s_.camera.origin;
        vec3 dirs[16];
        for (int l = 0; l < 16; ++l) {
            valid[l] = l < lanes ? -1 : 0;
            dirs[l] = cameraDirection(s_.camera, x0 + std::min(l, lanes - 1), y, 0.5f, 0.5f);
            rh.ray.org_x[l] = o.x;
            rh.ray.org_y[l] = o.y;
            rh.ray.org_z[l] = o.z;
            rh.ray.dir_x[l] = dirs[l].x;
            rh.ray.dir_y[l] = dirs[l].y;
            rh.ray.dir_z[l] = dirs[l].z;
            rh.ray.tnear[l] = 0.0f;
            rh.ray.tfar[l] = std::numeric_limits<float>::infinity();
            rh.ray.time[l] = 0.0f;
            rh.ray.mask[l] = ~0u;
            rh.ray.id[l] = 0;
            rh.ray.flags[l] = 0;
            rh.hit.geomID[l] = RTC_INVALID_GEOMETRY_ID;
        }
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        rtcIntersect16(valid, scene_, &context, &rh);
        counts_.camera += std::uint64_t(lanes);
        for (int l = 0; l < lanes; ++l) {
            std::optional<Hit> hit;
            if (rh.hit.geomID[l] != RTC_INVALID_GEOMETRY_ID)
                hit = Hit{rh.ray.tfar[l], s_.sphereOfPrim[rh.hit.primID[l]], rh.ray.tfar[l]};
            nearestBig(o, dirs[l], -1, false, hit);
            out[l] = shade(o, dirs[l], hit, 0);
        }
    }

    // Replaces `hit` by a huge sphere's nearer hit, by our self-intersection rule.
    void nearestBig(const vec3& o, const vec3& d, int origin, bool into,
                    std::optional<Hit>& hit) const {
        for (const Big& b : s_.big) {
            if (b.sphere == origin && !into) continue;
            const auto roots = bigRoots(b, glm::dvec3(o), glm::dvec3(d));
            if (!roots) continue;
            double t = roots->first > 0 && b.sphere != origin ? roots->first : roots->second;
            if (!(t > 0)) continue;
            if (!hit || t < hit->tDouble) hit = Hit{float(t), b.sphere, t};
        }
    }

    std::optional<Hit> closest(const vec3& o, const vec3& d, int origin, bool into) {
        RTCRayHit rh;
        rh.ray = {o.x,
                  o.y,
                  o.z,
                  kEmbreeRayOffset,
                  d.x,
                  d.y,
                  d.z,
                  0.0f,
                  std::numeric_limits<float>::infinity(),
                  ~0u,
                  0,
                  0};
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        rtcIntersect1(scene_, &context, &rh);
        std::optional<Hit> hit;
        if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID)
            hit = Hit{rh.ray.tfar, s_.sphereOfPrim[rh.hit.primID], rh.ray.tfar};
        nearestBig(o, d, origin, into, hit);
        return hit;
    }

    // The huge spheres' share of a shadow ray's transmittance, by our rules:
    // each sphere crossed within (0, distance) once; the ray's own sphere only
    // when it goes into it, by its far side.
    float bigTransmittance(const vec3& p, const vec3& l, float distance, int origin,
                           bool into) const {
        float s = 1.0f;
        for (const Big& b : s_.big) {
            const bool own = b.sphere == origin;
            if (own && !into) continue;
            const auto roots = bigRoots(b, glm::dvec3(p), glm::dvec3(l));
            if (!roots) continue;
            const auto within = [distance](double t) { return t > 0 && t < distance; };
            if (own ? within(roots->second) : within(roots->first) || within(roots->second))
                s *= s_.transparency[std::size_t(b.sphere)];
        }
        return s;
    }

    float transmittance(const vec3& p, const vec3& l, float distance, int origin, bool into) {
        const float big = bigTransmittance(p, l, distance, origin, into);
        if (big == 0.0f) return 0.0f;
        seen_.clear();
        ShadowContext c{{}, &s_, origin, into, 1.0f, &seen_};
        rtcInitIntersectContext(&c.context);
        RTCRay ray{p.x, p.y, p.z, kEmbreeRayOffset, l.x, l.y, l.z, 0.0f, distance, ~0u, 0, 0};
        rtcOccluded1(scene_, &c.context, &ray);
        return c.transmittance * big;
    }

    vec3 diffuseAt(const Mat& m, const glm::dvec3& p) const {
        if (m.checkerSize == 0) return m.diffuse;
        const double c = std::floor(p.x / m.checkerSize) + std::floor(p.y / m.checkerSize) +
                         std::floor(p.z / m.checkerSize);
        return std::fmod(c, 2.0) == 0 ? m.diffuse : m.checker;
    }

    vec3 shade(const vec3& o, const vec3& d, const std::optional<Hit>& hit, int depth) {
        if (!hit) return s_.background;
        const int k = hit->sphere;
        const Mat& m = s_.mats[s_.material[k]];
        const glm::dvec3 pd = glm::dvec3(o) + hit->tDouble * glm::dvec3(d);
        const vec3 p(pd);
        const int big = s_.bigOf[std::size_t(k)];
        const vec3 outward = big >= 0 ? vec3(glm::normalize(pd - s_.big[std::size_t(big)].centre))
                                      : glm::normalize(p - s_.centre[std::size_t(k)]);
        const bool inside = glm::dot(d, outward) > 0.0f;
        const vec3 n = inside ? -outward : outward;
        const vec3 kd = diffuseAt(m, pd);
        vec3 colour = s_.ambient * kd;
        for (std::size_t j = 0; j < s_.lightPos.size(); ++j)
            colour += direct(j, m, kd, p, d, n, outward, k);
        if (depth >= s_.maxDepth) return colour;
        float reflectWeight = m.kr;
        if (m.kt > 0.0f) {
            const float eta = inside ? m.ior : 1.0f / m.ior;
            const float cosi = -glm::dot(d, n);
            const float root2 = 1.0f - eta * eta * (1.0f - cosi * cosi);
            if (!(root2 >= 0.0f)) {
                reflectWeight += m.kt;
            } else {
                const vec3 t = glm::normalize(eta * d + (eta * cosi - std::sqrt(root2)) * n);
                ++counts_.refraction;
                colour += m.kt * shade(p, t, closest(p, t, k, !inside), depth + 1);
            }
        }
        if (reflectWeight > 0.0f) {
            const vec3 r = d - (2.0f * glm::dot(d, n)) * n;
            ++counts_.reflection;
            colour += reflectWeight * shade(p, r, closest(p, r, k, inside), depth + 1);
        }
        return colour;
    }

    vec3 direct(std::size_t j, const Mat& m, const vec3& kd, const vec3& p, const vec3& d,
                const vec3& n, const vec3& outward, int k) {
        vec3 l = s_.lightPos[j] - p;
        const float distance = std::sqrt(glm::dot(l, l));
        l = l * (1.0f / distance);
        const float nl = glm::dot(n, l);
        if (!(m.lit && distance > 0.0f && nl > 0.0f)) return vec3(0.0f);
        ++counts_.shadow;
        const float sj = transmittance(p, l, distance, k, glm::dot(l, outward) < 0.0f);
        if (sj == 0.0f) return vec3(0.0f);
        const vec3 h = glm::normalize(l - d);
        const float spec = m.ks * std::pow(std::max(0.0f, glm::dot(n, h)), m.shininess);
        return sj * s_.lightColor[j] * (kd * nl + spec);
    }

    const Shading& s_;
    RTCScene scene_;
    RayCounts& counts_;
    std::vector<unsigned> seen_;
};

Shading prepare(const Scene& scene) {
    Shading s;
    for (const Material& m : scene.materials) {
        Mat p{vec3(m.diffuse),
              vec3(m.checker ? m.checker->color : Vec3(0)),
              m.checker ? m.checker->size : 0.0,
              float(m.specular),
              float(m.shininess),
              float(m.reflectivity),
              float(m.transparency),
              float(m.ior),
              false};
        p.lit =
            m.diffuse != Vec3(0) || (m.checker && m.checker->color != Vec3(0)) || m.specular != 0;
        s.mats.push_back(p);
    }
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& sp = scene.spheres[i];
        s.centre.push_back(vec3(sp.center));
        s.material.push_back(findMaterial(scene, sp.material));
        s.transparency.push_back(s.mats[s.material.back()].kt);
        const bool huge = sp.radius >= kHugeRadius;
        s.bigOf.push_back(huge ? int(s.big.size()) : -1);
        if (huge)
            s.big.push_back({sp.center, sp.radius, int(i)});
        else
            s.sphereOfPrim.push_back(int(i));
    }
    for (const Light& l : scene.lights) {
        s.lightPos.push_back(vec3(l.position));
        s.lightColor.push_back(vec3(l.color * l.intensity));
    }
    s.background = vec3(scene.background);
    s.ambient = vec3(scene.ambient);
    s.maxDepth = scene.render.maxDepth;
    s.camera = makeCameraBasis<float>(scene.camera, scene.render.width, scene.render.height);
    return s;
}

RTCScene buildScene(RTCDevice device, const Scene& scene, const Shading& s, RTCBuildQuality q) {
    RTCScene rs = rtcNewScene(device);
    rtcSetSceneBuildQuality(rs, q);
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), s.sphereOfPrim.size()));
    for (std::size_t p = 0; p < s.sphereOfPrim.size(); ++p) {
        const Sphere& sp = scene.spheres[std::size_t(s.sphereOfPrim[p])];
        v[4 * p + 0] = float(sp.center.x);
        v[4 * p + 1] = float(sp.center.y);
        v[4 * p + 2] = float(sp.center.z);
        v[4 * p + 3] = float(sp.radius);
    }
    rtcSetGeometryBuildQuality(g, q);
    rtcSetGeometryOccludedFilterFunction(g, shadowFilter);
    rtcCommitGeometry(g);
    rtcAttachGeometry(rs, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(rs);
    check(device);
    return rs;
}

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

double bestBuild(RTCDevice device, const Scene& scene, const Shading& s, RTCBuildQuality q) {
    double best = 1e300;
    for (int i = 0; i < 3; ++i) {
        const auto start = std::chrono::steady_clock::now();
        RTCScene rs = buildScene(device, scene, s, q);
        best = std::min(best, msSince(start));
        rtcReleaseScene(rs);
    }
    return best;
}

}  // namespace

EmbreeRun renderWithEmbree(const Scene& scene, int threads) {
    const std::string config = "threads=" + std::to_string(threads);
    RTCDevice device = rtcNewDevice(config.c_str());
    if (!device) throw std::runtime_error("Embree: no device");
    EmbreeRun run;
    const Shading s = prepare(scene);
    run.buildHighMs = bestBuild(device, scene, s, RTC_BUILD_QUALITY_HIGH);
    run.buildMediumMs = bestBuild(device, scene, s, RTC_BUILD_QUALITY_MEDIUM);

    const int width = scene.render.width, height = scene.render.height;
    run.image = Image(width, height);
    const auto start = std::chrono::steady_clock::now();
    RTCScene rs = buildScene(device, scene, s, RTC_BUILD_QUALITY_HIGH);
    std::atomic<int> nextRow{0};
    std::vector<RayCounts> counts(static_cast<std::size_t>(threads));
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) {
        pool.emplace_back([&, t] {
            // Counted apart and added at the end: two threads' counters on one
            // cache line cost more than a small scene's whole render.
            RayCounts local;
            Tracer tracer(s, rs, local);
            std::vector<vec3> line(static_cast<std::size_t>(width));
            for (int y; (y = nextRow++) < height;) {
                tracer.row(y, line.data());
                for (int x = 0; x < width; ++x)
                    std::copy_n(&line[std::size_t(x)].x, 3, run.image.pixel(x, y));
            }
            counts[std::size_t(t)] = local;
        });
    }
    for (std::thread& t : pool) t.join();
    run.renderMs = msSince(start);
    for (const RayCounts& c : counts) run.rays += c;
    rtcReleaseScene(rs);
    rtcReleaseDevice(device);
    return run;
}

}  // namespace whitted
