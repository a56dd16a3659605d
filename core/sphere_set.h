// The scene's spheres as the tracer reads them: parallel arrays, prepared once
// per render by code built with the project's flags and then read by whichever
// kernel runs (core/kernel_dispatch.h), so it lives outside the per-ISA namespace.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "sphere_intersect.h"

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
    std::vector<Vec<T>> centre, centreLo;  // centre + centreLo: the centre, to ~eps(T)^2
    std::vector<T> radius, radiusLo;       // likewise the radius
    std::vector<T> rrHi, rrLo;             // radius^2 == rrHi + rrLo, to ~eps(T)^2
    std::vector<T> cameraC;                // accurateOffsetSquared() from the camera position

    int count() const { return static_cast<int>(centre.size()); }
    LeafSphere<T> leafSphere(int k) const { return {centre[k], rrHi[k], cameraC[k], k}; }

    // A sphere of the double scene: centre == c + cLo exactly (a two-term double,
    // as a translation in double leaves it) and radius r, both in this set's frame.
    void add(const glm::dvec3& c, const glm::dvec3& cLo, double r, const Vec<T>& camera) {
        Vec<T> hi, lo;
        for (int i = 0; i < 3; ++i) split(c[i], cLo[i], hi[i], lo[i]);
        double rr, rrErr;
        exact::twoProduct(r, r, rr, rrErr);
        T rrH, rrL, rH, rL;
        split(rr, rrErr, rrH, rrL);
        split(r, 0.0, rH, rL);
        centre.push_back(hi);
        centreLo.push_back(lo);
        radius.push_back(rH);
        radiusLo.push_back(rL);
        rrHi.push_back(rrH);
        rrLo.push_back(rrL);
        cameraC.push_back(accurateOffsetSquared(camera, hi, lo, rrH, rrL));
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
