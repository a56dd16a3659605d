// Property test: camera rays against random spheres, in float and in
// double, checked against a quad-precision answer.
//
// Spheres of radius 1e-4 to 1e4 (log-uniform), at 1.001 to 1e4 (float) or 1e7
// (double) radii from a camera anywhere within ~1e3 of the world origin. Rays from
// the camera (fromCamera, origin s.camera.origin) aim at random points of the
// sphere's disc and, more densely, at its silhouette (|h/r - 1| from 1e-10 to
// 0.1). The reference intersects the line from the scene's (double) camera
// position along the exact T direction the tracer was given with the scene's
// (double) sphere, in __float128.
//
// Band: delta = K eps (|o - c| + r), eps = std::numeric_limits<T>::epsilon(), K = 16.
// Why 16: a careful T implementation rounds the sphere centre into its frame
// (<= 0.9 eps |o - c| with a camera-centred frame), forms f = o - c and b = f.d
// (~3 eps |f|), the perpendicular f - b d (~2 eps |f| more), assumes |d| = 1 while
// the rounded direction is 1 +- 1.5 eps (~1.5 eps t), and takes a square root and
// a quotient: about 8 eps (|o - c| + r) in the worst case, so K = 16 is a factor
// two above that and still far below what any absolute epsilon or unscaled
// cancellation produces (those show up as ratios of 1e3 and more).
//
// Asserted, for every ray:
//  1. hit/miss: the tracer and the reference may disagree only within the band
//     of the silhouette, |h - r| <= delta (h: the reference's distance from the
//     centre to the ray);
//  2. a reported hit lies on the surface: | |o + t d - c| - r | <= delta (the
//     exact point at the returned t, in quad), and on the near side
//     (t <= t_closest + delta, t_closest: the ray's point nearest the centre);
//  3. |t - t_ref| <= delta, where the problem allows it: for rays meeting the
//     surface at up to 60 degrees from the normal (half chord >= r/2). Closer to
//     the silhouette t is ill-conditioned (dt/dh = h / sqrt(r^2 - h^2) grows
//     without bound), so no implementation in T can keep |dt| within delta there;
//     2. is the backward-error form of the same bound and covers those rays. The
//     largest |dt| / (eps (|o-c|+r)) over all rays is printed for information.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "support/numerics_support.h"

namespace whitted {
namespace {

using test::kBand;
using test::kSpheres;
using test::Quad;
using test::QVec;
using test::Rng;

constexpr int kRaysPerSphere = 16;

struct Tally {
    long rays = 0, referenceHits = 0, tracerHits = 0;
    long wrongHit = 0, wrongMiss = 0, wrongSphere = 0, offSurface = 0, farSide = 0, tOff = 0;
    // Rays failing any check, and those of them whose camera sits at the world
    // origin, where no frame can add rounding of the camera position.
    long failed = 0, raysAtOrigin = 0, failedAtOrigin = 0;
    test::Worst wrongHitWorst, wrongMissWorst, offSurfaceWorst, farSideWorst, tOffWorst;
    test::Worst dtWellConditioned, dtAll;
    // For information: the largest ratios over all hits, and over the rays from a
    // camera at the world origin (those show the intersection alone, without the
    // rounding of the camera position into a world-centred frame).
    test::Worst residualAll, residualAtOrigin, dtWellConditionedAtOrigin;
};

template <typename T>
void checkCameraRays() {
    const std::uint64_t seed = test::propertySeed();
    Rng rng(seed);
    const double eps = std::numeric_limits<T>::epsilon();
    const double maxRatio = sizeof(T) == sizeof(float) ? 1e4 : 1e7;
    Tally tally;

    for (int n = 0; n < kSpheres; ++n) {
        const double r = test::logUniform(rng, 1e-4, 1e4);
        // Camera anywhere up to ~1e3 from the world origin; every eighth exactly at it.
        const Vec3 cam =
            n % 8 == 0 ? Vec3(0.0) : test::randomUnit(rng) * test::logUniform(rng, 1e-3, 1e3);
        const double ratio = test::logUniform(rng, 1.001, maxRatio);
        const Vec3 centre = cam + test::randomUnit(rng) * (ratio * r);
        const Vec3 w = glm::normalize(centre - cam);

        const Scene scene = test::oneSphereScene(rng, cam, centre, r, test::precisionOf<T>());
        const PreparedScene<T> s = prepareScene<T>(scene);

        const QVec O(cam), C(centre);
        const Quad R = r;
        const double L = double(test::length(C - O));
        const double unit = eps * (L + r);  // eps (|o - c| + r)

        for (int j = 0; j < kRaysPerSphere; ++j) {
            double hOverR;
            if (j < 6) {
                hOverR = test::uniform(rng, 0.0, 0.999);  // the disc
            } else if (j == 6) {
                hOverR = 1.0;  // aimed at the silhouette itself
            } else {
                const double off = test::logUniform(rng, 1e-10, 0.1);
                hOverR = j % 2 ? 1 + off : 1 - off;
            }
            const double h = std::min(hOverR * r, 0.99999 * L);
            const Vec3 u = test::randomPerpendicular(rng, w);
            const double sinA = h / L, cosA = std::sqrt(1 - sinA * sinA);
            const Vec<T> d = glm::normalize(Vec<T>(cosA * w + sinA * u));
            const Ray<T> ray{s.camera.origin, d, -1, false, true};
            const std::optional<Hit<T>> hit = closestHit<T>(s, ray);
            const test::ReferenceHit ref = test::referenceIntersect(O, QVec(d), C, R);

            ++tally.rays;
            const bool atOrigin = cam == Vec3(0.0);
            tally.raysAtOrigin += atOrigin;
            const long failedBefore = tally.wrongHit + tally.wrongMiss + tally.wrongSphere +
                                      tally.offSurface + tally.farSide + tally.tOff;
            auto countFailure = [&] {
                const long now = tally.wrongHit + tally.wrongMiss + tally.wrongSphere +
                                 tally.offSurface + tally.farSide + tally.tOff;
                if (now == failedBefore) return;
                ++tally.failed;
                tally.failedAtOrigin += atOrigin;
            };
            tally.referenceHits += ref.hit;
            tally.tracerHits += hit.has_value();
            auto where = [&](double value) {
                std::ostringstream o;
                o.precision(17);
                o << value << " at sphere " << n << " ray " << j << ": r " << r << ", |o-c|/r "
                  << L / r << ", camera " << test::str(cam) << ", h/r - 1 "
                  << test::str((ref.h - R) / R) << ", tracer "
                  << (hit ? "t " + test::str(hit->t) : std::string("miss")) << ", reference "
                  << (ref.hit ? "t " + test::str(ref.tNear) : std::string("miss"));
                return o.str();
            };
            // Signed distance of the ray from the silhouette, in units of eps (|o-c|+r).
            const double fromSilhouette = double((ref.h - R) / unit);
            if (hit && !ref.hit && fromSilhouette > kBand) {
                ++tally.wrongHit;
                tally.wrongHitWorst.note(fromSilhouette, where(fromSilhouette));
            }
            if (!hit && ref.hit && -fromSilhouette > kBand) {
                ++tally.wrongMiss;
                tally.wrongMissWorst.note(-fromSilhouette, where(-fromSilhouette));
            }
            if (!hit) {
                countFailure();
                continue;
            }
            if (hit->sphere != 0) ++tally.wrongSphere;
            const Quad t = hit->t;
            const double residual =
                double(test::qabs(test::length(O + t * QVec(d) - C) - R) / unit);
            tally.residualAll.note(residual, where(residual));
            if (atOrigin) tally.residualAtOrigin.note(residual, where(residual));
            if (!(residual <= kBand)) {
                ++tally.offSurface;
                tally.offSurfaceWorst.note(residual, where(residual));
            }
            const double beyond = double((t - ref.tClosest) / unit);
            if (beyond > kBand) {
                ++tally.farSide;
                tally.farSideWorst.note(beyond, where(beyond));
            }
            if (!ref.hit) {
                countFailure();
                continue;
            }
            const double dt = double(test::qabs(t - ref.tNear) / unit);
            tally.dtAll.note(dt, where(dt));
            if (ref.halfChord >= R / 2) {
                tally.dtWellConditioned.note(dt, where(dt));
                if (atOrigin) tally.dtWellConditionedAtOrigin.note(dt, where(dt));
                if (!(dt <= kBand)) {
                    ++tally.tOff;
                    tally.tOffWorst.note(dt, where(dt));
                }
            }
            countFailure();
        }
    }

    std::cout << "[ MEASURED ] " << test::precisionLabel<T>() << ": " << tally.rays << " rays, "
              << tally.referenceHits << " reference hits, " << tally.tracerHits
              << " tracer hits; band K = " << kBand << "\n"
              << "  wrong hits " << tally.wrongHit << " (worst " << tally.wrongHitWorst.where
              << ")\n"
              << "  wrong misses " << tally.wrongMiss << " (worst " << tally.wrongMissWorst.where
              << ")\n"
              << "  off the surface " << tally.offSurface << " (worst "
              << tally.offSurfaceWorst.where << ")\n"
              << "  far side " << tally.farSide << " (worst " << tally.farSideWorst.where << ")\n"
              << "  |dt| > K eps (|o-c|+r) at <= 60 degrees " << tally.tOff
              << "; largest |dt|/(eps (|o-c|+r)) there: " << tally.dtWellConditioned.where << "\n"
              << "  largest |dt|/(eps (|o-c|+r)) over all hits (information): " << tally.dtAll.where
              << "\n"
              << "  rays failing any check " << tally.failed << " of " << tally.rays
              << "; with the camera at the world origin " << tally.failedAtOrigin << " of "
              << tally.raysAtOrigin << "\n"
              << "  largest | |o+td-c| - r | / (eps (|o-c|+r)): " << tally.residualAll.value
              << "; camera at the origin: " << tally.residualAtOrigin.value << "\n"
              << "  largest |dt|/(eps (|o-c|+r)) at <= 60 degrees, camera at the origin: "
              << tally.dtWellConditionedAtOrigin.value << std::endl;
    EXPECT_EQ(tally.wrongHit, 0) << "worst " << tally.wrongHitWorst.where;
    EXPECT_EQ(tally.wrongMiss, 0) << "worst " << tally.wrongMissWorst.where;
    EXPECT_EQ(tally.wrongSphere, 0);
    EXPECT_EQ(tally.offSurface, 0) << "worst " << tally.offSurfaceWorst.where;
    EXPECT_EQ(tally.farSide, 0) << "worst " << tally.farSideWorst.where;
    EXPECT_EQ(tally.tOff, 0) << "worst " << tally.tOffWorst.where;
}

TEST(NumericsIntersection, CameraRaysFloat_RandomSpheres_WithinErrorBand) {
    checkCameraRays<float>();
}

TEST(NumericsIntersection, CameraRaysDouble_RandomSpheres_WithinErrorBand) {
    checkCameraRays<double>();
}

}  // namespace
}  // namespace whitted
