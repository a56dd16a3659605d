// Property test, pbrt style: rays spawned from a hit never find their
// own surface again, and rays going into the sphere always find its far side.
//
// Spheres of radius 1e-4 to 1e4 placed up to 1e6 (float) or 1e12 (double) from the
// world origin (log-uniform distance; every eighth at the origin), the camera 1.5
// to 10 radii from the centre. A camera ray aimed inside the disc (h <= 0.9 r)
// gives p = origin + t d, computed in T as the tracer computes hit points. The
// tangent plane at p is the one of the prepared sphere (its T centre), through p.
// From p, for directions uniform on the hemisphere and for grazing directions
// 1e-3 and 1e-6 radians from the tangent plane:
//  - leaving outwards (originSphere 0, intoOrigin false): closestHit on the
//    scene of that sphere alone reports nothing;
//  - a shadow ray to a light outside the sphere, in the outer half-space of the
//    tangent plane (opaque sphere): S == 1 exactly, through packetTransmittance as
//    tracer.cpp forms shadow rays (tests/support/numerics_support.h);
//  - going inwards (intoOrigin true): a hit on the sphere with t > 0 whose exact
//    point p + t d (quad, world frame) lies within K eps (r + |p - camera|) of the
//    scene's sphere, K = 16 as in test_numerics_intersection.cpp. The bound scales
//    with the sphere and the camera distance, not with the distance from the world
//    origin: a camera near a far sphere must see it as well as one near the origin.
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

constexpr int kRaysPerClass = 3;  // per sphere, per direction class, outwards and inwards
constexpr int kClasses = 3;
const char* const kClassNames[kClasses] = {"hemisphere", "grazing 1e-3", "grazing 1e-6"};

struct ClassTally {
    long outward = 0, selfHits = 0;
    long inward = 0, noExit = 0, exitOff = 0;
    long shadow = 0, selfShadowed = 0, shadowSkipped = 0;
    // Of the failures above, those of spheres centred at the world origin, where a
    // world-centred frame adds no rounding of its own.
    long failedAtOrigin = 0, atOrigin = 0;
    test::Worst selfHitWorst, noExitWorst, exitOffWorst, selfShadowWorst;
};

template <typename T>
void checkReintersection() {
    const std::uint64_t seed = test::propertySeed();
    Rng rng(seed);
    const double eps = std::numeric_limits<T>::epsilon();
    const double maxDistance = sizeof(T) == sizeof(float) ? 1e6 : 1e12;
    long cameraMisses = 0;
    test::Worst cameraMissWorst;
    ClassTally tally[kClasses];

    for (int n = 0; n < kSpheres; ++n) {
        const double r = test::logUniform(rng, 1e-4, 1e4);
        const Vec3 centre = n % 8 == 0
                                ? Vec3(0.0)
                                : test::randomUnit(rng) * test::logUniform(rng, 1.0, maxDistance);
        const Vec3 cam = centre + test::randomUnit(rng) * (r * test::logUniform(rng, 1.5, 10));
        const Vec3 w = glm::normalize(centre - cam);
        const bool atOrigin = centre == Vec3(0.0);

        const Scene scene = test::oneSphereScene(rng, cam, centre, r, test::precisionOf<T>());
        const PreparedScene<T> s = prepareScene<T>(scene);

        auto describe = [&](const std::string& what) {
            std::ostringstream o;
            o.precision(17);
            o << what << " at sphere " << n << ": r " << r << ", centre " << test::str(centre)
              << ", camera " << test::str(cam);
            return o.str();
        };

        const double h = r * test::uniform(rng, 0.0, 0.9);
        const double L = glm::length(centre - cam);
        const Vec3 aimPerp = test::randomPerpendicular(rng, w);
        const Vec<T> aim =
            glm::normalize(Vec<T>(std::sqrt(1 - (h / L) * (h / L)) * w + (h / L) * aimPerp));
        const std::optional<Hit<T>> camHit =
            closestHit<T>(s, Ray<T>{s.camera.origin, aim, -1, false, true});
        if (!camHit || camHit->sphere != 0) {
            ++cameraMisses;
            cameraMissWorst.note(
                1, describe("camera ray aimed at h/r " + std::to_string(h / r) + " missed"));
            continue;
        }
        const Vec<T> p = s.camera.origin + camHit->t * aim;  // as the tracer forms hit points
        const Vec<T> cT = s.spheres.centre[0];
        const Vec3 normal = glm::normalize(Vec3(p) - Vec3(cT));  // tangent plane at p
        if (!std::isfinite(normal.x) || !std::isfinite(normal.y) || !std::isfinite(normal.z)) {
            ++cameraMisses;  // no tangent plane: the hit point is the prepared centre
            cameraMissWorst.note(1, describe("camera hit point equals the prepared centre"));
            continue;
        }
        const QVec pWorld = QVec(s.frameOrigin) + QVec(Vec3(p));
        const QVec C(centre), cameraWorld(cam);
        const Quad R = r;
        const double exitUnit = eps * (r + double(test::length(pWorld - cameraWorld)));

        for (int cls = 0; cls < kClasses; ++cls) {
            ClassTally& ct = tally[cls];
            auto elevation = [&] {
                if (cls == 1) return 1e-3;
                if (cls == 2) return 1e-6;
                return std::asin(test::uniform(rng, 1e-9, 1.0));  // uniform on the hemisphere
            };
            for (int j = 0; j < kRaysPerClass; ++j) {
                const Vec3 tangent = test::randomPerpendicular(rng, normal);
                const double a = elevation();
                const Vec3 out = std::cos(a) * tangent + std::sin(a) * normal;
                const Vec3 in = std::cos(a) * tangent - std::sin(a) * normal;

                ++ct.outward;
                ct.atOrigin += 2 * atOrigin;  // this ray and the inward one
                const Vec<T> dOut = glm::normalize(Vec<T>(out));
                if (const auto self = closestHit<T>(s, Ray<T>{p, dOut, 0, false, false})) {
                    ++ct.selfHits;
                    ct.failedAtOrigin += atOrigin;
                    ct.selfHitWorst.note(
                        1, describe("outward ray at elevation " + test::str(Quad(a)) + " hit t " +
                                    test::str(Quad(self->t))));
                }

                ++ct.inward;
                const Vec<T> dIn = glm::normalize(Vec<T>(in));
                const auto exit = closestHit<T>(s, Ray<T>{p, dIn, 0, true, false});
                if (!exit || exit->sphere != 0 || !(exit->t > T(0))) {
                    ++ct.noExit;
                    ct.failedAtOrigin += atOrigin;
                    ct.noExitWorst.note(
                        1, describe("inward ray at elevation " + test::str(Quad(a)) +
                                    (exit ? " hit t " + test::str(Quad(exit->t)) : " missed")));
                } else {
                    const QVec x = pWorld + Quad(exit->t) * QVec(dIn);
                    const double off = double(test::qabs(test::length(x - C) - R)) / exitUnit;
                    if (!(off <= kBand)) {
                        ++ct.exitOff;
                        ct.failedAtOrigin += atOrigin;
                        ct.exitOffWorst.note(
                            off, describe("exit " + std::to_string(off) +
                                          " eps (r + |p - camera|) off the surface, elevation " +
                                          test::str(Quad(a))));
                    }
                }
            }

            // A light outside the sphere, above p's tangent plane.
            const Vec3 tangent = test::randomPerpendicular(rng, normal);
            const double a = elevation();
            const Vec3 out = std::cos(a) * tangent + std::sin(a) * normal;
            const double lightDistance = r * test::logUniform(rng, 0.1, 1e3);
            const Vec3 lightWorld = Vec3(s.frameOrigin) + Vec3(p) + lightDistance * out;
            Scene lit = scene;
            lit.lights = {test::makeLight("l", lightWorld)};
            const PreparedScene<T> s2 = prepareScene<T>(lit);
            ASSERT_EQ(s2.frameOrigin, s.frameOrigin) << "a light moved the prepared frame";
            const Vec<T> light = s2.lights[0].position;
            const Vec3 lightFromP = Vec3(light) - Vec3(p);
            if (!(glm::dot(lightFromP, normal) > 0) ||
                !(glm::length(Vec3(light) - Vec3(cT)) > double(s2.spheres.radius[0]))) {
                ++ct.shadowSkipped;  // rounding the light into T moved it below the plane
                continue;
            }
            ++ct.shadow;
            ct.atOrigin += atOrigin;
            const T S = test::shadowTransmittance(s2, p, 0, light);
            if (S != T(1)) {
                ++ct.selfShadowed;
                ct.failedAtOrigin += atOrigin;
                ct.selfShadowWorst.note(
                    1, describe("shadow ray at elevation " + test::str(Quad(a)) + ", light at " +
                                test::str(lightWorld) + ": S = " + test::str(Quad(S))));
            }
        }
    }

    std::cout << "[ MEASURED ] " << test::precisionLabel<T>() << ": " << kSpheres
              << " spheres, camera rays that missed their sphere or hit its centre: "
              << cameraMisses << " (" << cameraMissWorst.where << ")\n";
    for (int cls = 0; cls < kClasses; ++cls) {
        const ClassTally& ct = tally[cls];
        std::cout << "  " << kClassNames[cls] << ": outward self-hits " << ct.selfHits << "/"
                  << ct.outward << ", inward without exit " << ct.noExit << "/" << ct.inward
                  << ", exits off the surface " << ct.exitOff << " (worst " << ct.exitOffWorst.where
                  << "), self-shadowed " << ct.selfShadowed << "/" << ct.shadow << " (skipped "
                  << ct.shadowSkipped << "); failures with the sphere at the world origin "
                  << ct.failedAtOrigin << " of " << ct.atOrigin << " checks\n";
    }
    std::cout << std::flush;
    EXPECT_EQ(cameraMisses, 0) << cameraMissWorst.where;
    for (int cls = 0; cls < kClasses; ++cls) {
        const ClassTally& ct = tally[cls];
        SCOPED_TRACE(kClassNames[cls]);
        EXPECT_EQ(ct.selfHits, 0) << ct.selfHitWorst.where;
        EXPECT_EQ(ct.noExit, 0) << ct.noExitWorst.where;
        EXPECT_EQ(ct.exitOff, 0) << ct.exitOffWorst.where;
        EXPECT_EQ(ct.selfShadowed, 0) << ct.selfShadowWorst.where;
    }
}

TEST(NumericsReintersection, SpawnedRaysFloat_FarSpheres_NeverSelfHitAlwaysExit) {
    checkReintersection<float>();
}

TEST(NumericsReintersection, SpawnedRaysDouble_FarSpheres_NeverSelfHitAlwaysExit) {
    checkReintersection<double>();
}

}  // namespace
}  // namespace whitted
