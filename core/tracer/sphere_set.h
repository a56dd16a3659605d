// The scene's spheres as the tracer reads them: parallel arrays, prepared once
// per render by code built with the project's flags and then read by whichever
// kernel runs (core/tracer/kernel_dispatch.h), so it lives outside the per-ISA namespace.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "base/uninitialised_allocator.h"
#include "tracer/sphere_intersect.h"

namespace whitted {

// What every sphere test reads of sphere `index` (intersectPacket()); the
// rarely needed low terms stay in the SphereSet. The sphere tree keeps these in
// leaf order (SphereBvh::leafSpheres), so the spheres of a leaf are one or two
// cache lines rather than a line per array per sphere: a million spheres do
// not fit in cache, and those lines were most of a render's misses.
template <typename T>
struct LeafSphere {
    Vec<T> centre;
    T rrHi;
    T cameraC;
    std::int32_t index;
};

// The scene's spheres as parallel arrays: all that intersection reads.
//
// Centres and radii are kept as two-term values (hi in T plus the part T drops)
// because a huge sphere is not representable in float otherwise: the seed's
// floor scaled by 1e4 has centre and radius near 1e9, where floats are 64 apart,
// so rounding each to float moves its top by up to 64 in a scene 8500 high. The
// near-surface computations (accurateOffsetSquared, the checker's steep axis) use
// both terms and so see the double scene's sphere; everything else uses hi.
template <typename T>
struct SphereSet {
    // Not zeroed on resize (uninitialised_allocator.h): a million spheres'
    // arrays are filled in parallel by prepareScene, each element once.
    template <typename E>
    using Array = std::vector<E, UninitialisedAllocator<E>>;
    Array<Vec<T>> centre, centreLo;  // centre + centreLo: the centre, to ~eps(T)^2
    Array<T> radius, radiusLo;       // likewise the radius
    Array<T> rrHi, rrLo;             // radius^2 == rrHi + rrLo, to ~eps(T)^2
    Array<T> cameraC;                // accurateOffsetSquared() from the camera position

    int count() const { return static_cast<int>(centre.size()); }
    // Sphere k's centre and radius in double, both terms added: for the
    // bounds made once a render (screen_boxes.h, shadow_cones.h).
    glm::dvec3 centreOf(int k) const { return glm::dvec3(centre[k]) + glm::dvec3(centreLo[k]); }
    double radiusOf(int k) const { return double(radius[k]) + double(radiusLo[k]); }
    LeafSphere<T> leafSphere(int k) const { return {centre[k], rrHi[k], cameraC[k], k}; }

    // Room for n spheres, each to be given by set() (or place() and its camera term): a large
    // scene's spheres are prepared on all cores, each into its own place.
    void resize(std::size_t n) {
        centre.resize(n);
        centreLo.resize(n);
        radius.resize(n);
        radiusLo.resize(n);
        rrHi.resize(n);
        rrLo.resize(n);
        cameraC.resize(n);
    }
    // Sphere k is a sphere of the double scene: centre == c + cLo exactly (a
    // two-term double, as a translation in double leaves it) and radius r, both
    // in this set's frame.
    void set(int k, const glm::dvec3& c, const glm::dvec3& cLo, double r, const Vec<T>& camera) {
        place(k, c, cLo, r);
        cameraC[k] = accurateOffsetSquared(camera, centre[k], centreLo[k], rrHi[k], rrLo[k]);
    }
    // set() but the camera term, which is left for the caller to compute.
    void place(int k, const glm::dvec3& c, const glm::dvec3& cLo, double r) {
        for (int i = 0; i < 3; ++i) split(c[i], cLo[i], centre[k][i], centreLo[k][i]);
        double rr, rrErr;
        exact::twoProduct(r, r, rr, rrErr);
        split(rr, rrErr, rrHi[k], rrLo[k]);
        split(r, 0.0, radius[k], radiusLo[k]);
    }
    // The same, as a sphere more.
    void add(const glm::dvec3& c, const glm::dvec3& cLo, double r, const Vec<T>& camera) {
        for (auto* a : {&centre, &centreLo}) a->emplace_back();
        for (auto* a : {&radius, &radiusLo, &rrHi, &rrLo, &cameraC}) a->emplace_back();
        set(count() - 1, c, cLo, r, camera);
    }
    // A sphere whose centre and radius T holds exactly.
    void add(const Vec<T>& c, T r, const Vec<T>& camera) {
        add(glm::dvec3(c), glm::dvec3(0.0), double(r), camera);
    }

  private:
    // hi + lo == h + l, hi = T(h) rounded, lo what hi lost (rounded to T).
    // The rounded value goes through a volatile: GCC 12's SLP vectoriser at -O2
    // otherwise rewrites double(T(h)) in these few lines so that lo comes out
    // wrong by about one ulp of hi, or zero where it should not be
    // (tests/core/test_ray_packet.cpp, TwoTermCentreKeepsWhatFloatDrops).
    static void split(double h, double l, T& hi, T& lo) {
        const volatile T rounded = T(h);
        hi = rounded;
        lo = T((h - double(hi)) + l);
    }
};

}  // namespace whitted
