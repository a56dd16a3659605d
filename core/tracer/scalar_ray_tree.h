// One pixel's Whitted ray tree walked ray by ray: a second statement of the
// tracer's recursion (tracer_kernel.cpp's tracePacket), in scalar form,
// expression for expression, kept on purpose. The packet kernel is SIMD-wide
// and adds up radiance; this walk follows one ray at a time and lets a
// visitor see each decision instead: closest hit, per-light shadow rays
// through sceneTransmittance, refraction before reflection, total internal
// reflection sending kt along the reflected ray, the same self-intersection
// policy and depth limit. It adds up no radiance. Used for the float/double
// decision counts (core/analysis/ray_decisions.h) and the depth truncation
// map (core/analysis/depth_truncation.h).
//
// Being a second statement, it is an oracle held against the first: change
// the two together. tests/core/test_scalar_ray_tree.cpp checks that over
// random fields of matte, mirror and glass balls it traces exactly the rays
// the tracer traces, at every depth and in both precisions;
// test_ray_decisions checks that its hits and shadows are the rendered pixels'.
#pragma once

#include <cmath>
#include <optional>

#include "tracer/bvh_traverse.h"
#include "tracer/ray_packet.h"
#include "tracer/tracer.h"

namespace whitted {

// Which ray of the tree trace() follows.
enum class TreeRay { Camera, Reflection, Refraction };

// The visitor provides:
//   static constexpr bool kWantsShadows;   // evaluate shadow rays at all
//   void hit(int sphere);                   // each ray's hit, -1 for a miss
//   void shadow(int shadowed);              // per light at a hit: 1 when S_j < 1
//                                           // (0 where the light is not tested)
//   void tir(bool total);                   // at a transparent hit below max_depth
//   void cutOff(T weight);                  // a hit at max_depth whose kr + kt > 0:
//                                           // its path weight times kr + kt
//   bool descend(T weight, int depth);      // trace a secondary ray of this path
//                                           // weight and depth (false: skip it)
// and, to follow the tree itself (analysis/pixel_ray_tree.h), optionally:
//   void enter(TreeRay, const Ray<T>&, const std::optional<Hit<T>>&, int depth, T weight);
//   void leave();                           // after the ray's shadows and children
//   void shadowRay(int light, const Vec<T>& p, const Vec<T>& l, T distance, T sj);
template <typename T, typename Visitor>
class ScalarRayTree {
  public:
    ScalarRayTree(const PreparedScene<T>& s, Visitor& visitor) : s_(s), v_(visitor) {}

    static constexpr bool kFollowsTree = requires(Visitor & v) { v.leave(); };

    // `weight`: the product of the kr / kt factors from the camera ray to this ray.
    void trace(const Ray<T>& ray, int depth, T weight, TreeRay kind = TreeRay::Camera) {
        const std::optional<Hit<T>> hit = closestHit(s_, ray);
        v_.hit(hit ? hit->sphere : -1);
        if constexpr (kFollowsTree) v_.enter(kind, ray, hit, depth, weight);
        if (hit) walk(ray, *hit, depth, weight);
        if constexpr (kFollowsTree) v_.leave();
    }

    // The camera ray through pixel (i, j)'s centre, as the tracer's camera rows
    // compute it for one sample per pixel.
    void tracePixel(int i, int j) {
        const Vec<T> dir = cameraDirection(s_.camera, i, j, T(0.5), T(0.5));
        trace(Ray<T>{s_.camera.origin, dir, -1, false, true}, 0, T(1));
    }

  private:
    // What follows a hit: its shadow rays, then its refracted and reflected rays.
    void walk(const Ray<T>& ray, const Hit<T>& hit, int depth, T weight) {
        const int k = hit.sphere;
        const PreparedMaterial<T>& m = s_.materials[s_.material[k]];
        const Vec<T> d = ray.dir;
        const Vec<T> p = ray.origin + hit.t * d;
        const Vec<T> outward = glm::normalize(p - s_.spheres.centre[k]);
        const bool inside = glm::dot(d, outward) > T(0);
        const Vec<T> n = inside ? -outward : outward;
        if constexpr (Visitor::kWantsShadows) {
            for (std::size_t light = 0; light < s_.lights.size(); ++light)
                v_.shadow(shadowed(int(light), p, n, outward, k, m.lit));
        }
        if (depth >= s_.maxDepth) {
            const T passedOn = m.reflectivity + m.transparency;
            if (passedOn > T(0)) v_.cutOff(weight * passedOn);
            return;
        }

        T reflectWeight = m.reflectivity;
        if (m.transparency > T(0)) {
            const T eta = inside ? m.ior : T(1) / m.ior;
            const T cosi = -glm::dot(d, n);
            const T root2 = T(1) - eta * eta * (T(1) - cosi * cosi);
            const bool tir = !(root2 >= T(0));
            v_.tir(tir);
            if (tir) {
                reflectWeight = reflectWeight + m.transparency;
            } else {
                const Vec<T> t = glm::normalize(eta * d + (eta * cosi - std::sqrt(root2)) * n);
                const T w = weight * m.transparency;
                if (v_.descend(w, depth + 1))
                    trace(Ray<T>{p, t, k, !inside, false}, depth + 1, w, TreeRay::Refraction);
            }
        }
        if (reflectWeight > T(0)) {
            const Vec<T> r = d - (T(2) * glm::dot(d, n)) * n;
            const T w = weight * reflectWeight;
            if (v_.descend(w, depth + 1))
                trace(Ray<T>{p, r, k, inside, false}, depth + 1, w, TreeRay::Reflection);
        }
    }

    // 1 when the light is tested and something on the way dims it (S_j < 1).
    int shadowed(int lightIndex, const Vec<T>& p, const Vec<T>& n, const Vec<T>& outward,
                 int sphere, bool lit) const {
        const PreparedLight<T>& light = s_.lights[std::size_t(lightIndex)];
        Vec<T> l = light.position - p;
        const T distance = std::sqrt(glm::dot(l, l));
        l = l * (T(1) / distance);
        const T nl = glm::dot(n, l);
        if (!(lit && distance > T(0) && nl > T(0))) return 0;
        // A one-lane packet, as closestHit() builds one: the tracer's own shadow test.
        RayPacket<T> shadow;
        shadow.set(0, p, l, sphere, glm::dot(l, outward) < T(0));
        const typename Simd<T>::type limit = typename Simd<T>::type{} + distance;
        const T sj = sceneTransmittance(s_.spheres, s_.transparency,
                                        s_.useBvh ? s_.bvh.get() : nullptr, shadow, limit, 1u)[0];
        if constexpr (kFollowsTree) v_.shadowRay(lightIndex, p, l, distance, sj);
        return sj < T(1) ? 1 : 0;
    }

    const PreparedScene<T>& s_;
    Visitor& v_;
};

}  // namespace whitted
