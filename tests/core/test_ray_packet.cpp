// The SIMD path (ray_packet.h: several rays against one sphere) must give
// exactly the roots of the scalar intersectSphere() for every lane, or renders
// would depend on which rays happen to share a packet. Seeded random rays, seed
// printed on failure.
#include <cmath>
#include <cstring>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "support/core_support.h"
#include "tracer/ray_packet.h"
#include "tracer/sphere_intersect.h"
#include "tracer/tracer.h"

namespace whitted {
namespace {

// Spheres from radius 1e-3 to 10 around the origin, and first a huge floor
// sphere (the seed's) whose surface passes near the origin.
template <typename T>
SphereSet<T> makeSpheres(std::mt19937& rng, int count, const Vec<T>& camera) {
    std::uniform_real_distribution<double> pos(-5.0, 5.0), logR(-3.0, 1.0);
    SphereSet<T> s;
    s.add(Vec<T>(T(0), T(-99999.5), T(0)), T(99999), camera);
    for (int k = 1; k < count; ++k)
        s.add(Vec<T>(T(pos(rng)), T(pos(rng)), T(pos(rng))), T(std::pow(10.0, logR(rng))), camera);
    return s;
}

template <typename T>
Vec<T> randomDirection(std::mt19937& rng) {
    std::normal_distribution<double> g;
    return Vec<T>(glm::normalize(glm::dvec3(g(rng), g(rng), g(rng))));
}

template <typename T>
void expectSameRoots(std::optional<SphereRoots<T>> scalar, bool valid, T tNear, T tFar,
                     unsigned seed, int ray, int sphere) {
    ASSERT_EQ(scalar.has_value(), valid)
        << "seed " << seed << " ray " << ray << " sphere " << sphere;
    if (!valid) return;
    // Bit-identical: compare with ==, not a tolerance.
    EXPECT_EQ(scalar->tNear, tNear) << "seed " << seed << " ray " << ray << " sphere " << sphere;
    EXPECT_EQ(scalar->tFar, tFar) << "seed " << seed << " ray " << ray << " sphere " << sphere;
}

template <typename T>
void checkPacketsMatchScalar(unsigned seed) {
    std::mt19937 rng(seed);
    const Vec<T> camera(T(0), T(0.35), T(-1));
    const int sphereCount = 11;
    const SphereSet<T> s = makeSpheres<T>(rng, sphereCount, camera);
    std::uniform_real_distribution<double> pos(-3.0, 3.0);
    constexpr int W = RayPacket<T>::kWidth;
    int hits = 0;

    for (int trial = 0; trial < 200; ++trial) {
        const bool fromCamera = trial % 2 == 0;
        RayPacket<T> packet;
        packet.active = (1u << W) - 1;
        packet.fromCamera = fromCamera;
        for (int l = 0; l < W; ++l) {
            // Secondary rays start on the floor's surface half the time: the
            // near-surface path with its exact fix-up.
            Vec<T> o = camera;
            if (!fromCamera)
                o = l % 2 ? Vec<T>(T(pos(rng)), T(-0.5), T(pos(rng)))
                          : Vec<T>(T(pos(rng)), T(pos(rng)), T(pos(rng)));
            packet.set(l, o, randomDirection<T>(rng), -1, false);
        }
        for (int k = 0; k < sphereCount; ++k) {
            const PacketRoots<T> pr = intersectPacket(s, k, packet, packet.active);
            for (int l = 0; l < W; ++l) {
                const T* knownC = fromCamera ? &s.cameraC[k] : nullptr;
                const auto scalar = intersectSphere(packet.origin(l), packet.dir(l), s.centre[k],
                                                    s.rrHi[k], s.rrLo[k], knownC);
                expectSameRoots(scalar, bool((pr.valid >> l) & 1u), pr.tNear[l], pr.tFar[l], seed,
                                trial * W + l, k);
                hits += scalar.has_value();
            }
        }
    }
    EXPECT_GT(hits, 200 * W / 4) << "seed " << seed << ": too few hits to compare";
}

TEST(RayPacket, LanesMatchScalarIntersectionBitForBit_Float) {
    for (unsigned seed : {1u, 2u, 3u}) checkPacketsMatchScalar<float>(seed);
}

TEST(RayPacket, LanesMatchScalarIntersectionBitForBit_Double) {
    for (unsigned seed : {1u, 2u, 3u}) checkPacketsMatchScalar<double>(seed);
}

// A ray traced alone (traceRay) and the same ray as one lane of a full packet of
// camera rays (traceCameraSamples) give the same radiance bit for bit.
TEST(RayPacket, CameraRayAloneEqualsCameraRayInPacket) {
    Scene scene;
    scene.camera = Camera{{0, 0.35, -1}, {0, 0.25, 0}, {0, 1, 0}, 73.74};
    scene.render.width = 64;
    scene.render.height = 48;
    scene.render.maxDepth = 3;
    scene.materials = {
        Material{"glass", {0, 0, 0}, 1, 200, 0.1, 0.9, 1.5, std::nullopt},
        Material{"floor", {0.75, 0.75, 0.75}, 1, 50, 0.25, 0, 1.5, Checker{{0, 0, 0}, 0.5}}};
    scene.lights = {Light{"key", {5, 5, -10}, {1, 1, 1}, 1}};
    scene.spheres = {Sphere{"ball", {0, 0.2, 2}, 0.6, "glass"},
                     Sphere{"floor", {0, -99999.5, 0}, 99999, "floor"}};
    const PreparedScene<float> s = prepareScene<float>(scene);
    std::vector<CameraSample<float>> samples;
    for (int j = 0; j < scene.render.height; ++j)
        for (int i = 0; i < scene.render.width; ++i) samples.push_back({i, j, 0.5f, 0.5f});
    std::vector<Vec<float>> packed(samples.size());
    RayCounts packedCounts, aloneCounts;
    traceCameraSamples(s, samples.data(), int(samples.size()), packed.data(), packedCounts);
    for (size_t n = 0; n < samples.size(); ++n) {
        const Vec<float> alone =
            tracePixelSample(s, samples[n].i, samples[n].j, 0.5f, 0.5f, aloneCounts);
        ASSERT_EQ(alone, packed[n]) << "pixel " << samples[n].i << "," << samples[n].j;
    }
    EXPECT_EQ(aloneCounts.total(), packedCounts.total());
    EXPECT_GT(packedCounts.refraction, 0u);  // the test does go through the glass
}

}  // namespace
}  // namespace whitted

namespace whitted {
namespace {

// The renderer's row path (traceCameraRow, its samples made for the packet's
// pixels at once), its path of several rows (traceCameraRows, a packet a
// block of pixels several rows tall) and the list path (traceCameraSamples
// with pixelSample, one pixel at a time) agree bit for bit: one sample,
// Kensler's pattern of many, and the open-ended sequence adaptive renders use.
template <typename T>
void checkRowMatchesList(int samplesPerPixel, bool openEnded = false) {
    Scene scene;
    scene.camera = Camera{{0, 0.35, -1}, {0, 0.25, 0}, {0, 1, 0}, 73.74};
    scene.render.width = 37;  // not a multiple of any packet width
    scene.render.height = 5;
    scene.render.samplesPerPixel = samplesPerPixel;
    scene.materials = {Material{"m", {0.5, 0.2, 0.1}, 1, 50, 0.5, 0, 1.5, Checker{{0, 0, 0}, 0.5}}};
    scene.lights = {Light{"key", {5, 5, -10}, {1, 1, 1}, 1}};
    scene.spheres = {Sphere{"ball", {0, 0.2, 2}, 0.6, "m"},
                     Sphere{"floor", {0, -99999.5, 0}, 99999, "m"}};
    PreparedScene<T> s = prepareScene<T>(scene);
    s.openEndedSamples = openEnded;
    for (int y = 0; y < scene.render.height; ++y)
        for (int n = 0; n < samplesPerPixel; ++n) {
            std::vector<Vec<T>> row(scene.render.width), list(scene.render.width);
            std::vector<CameraSample<T>> samples;
            for (int x = 0; x < scene.render.width; ++x) samples.push_back(pixelSample(s, x, y, n));
            RayCounts a, b;
            traceCameraRow(s, y, 0, scene.render.width, n, row.data(), a);
            traceCameraSamples(s, samples.data(), int(samples.size()), list.data(), b);
            for (int x = 0; x < scene.render.width; ++x)
                ASSERT_EQ(row[x], list[x]) << "pixel " << x << "," << y << " sample " << n;
            EXPECT_EQ(a.total(), b.total());
        }
    // Blocks as tall as the packets have rows and shorter ones (5 rows from
    // the top, 3 from the second row), 37 pixels wide, 3 from the 34th.
    const int width = scene.render.width;
    struct Rows {
        int y, rows, x0, count;
    };
    for (const Rows& r : {Rows{0, 5, 0, width}, Rows{1, 3, 0, width}, Rows{2, 2, 34, 3}})
        for (int n = 0; n < samplesPerPixel; ++n) {
            std::vector<Vec<T>> block(std::size_t(r.rows) * r.count);
            RayCounts a, b;
            traceCameraRows(s, r.y, r.rows, r.x0, r.count, n, block.data(), a);
            for (int j = 0; j < r.rows; ++j)
                for (int i = 0; i < r.count; ++i) {
                    const CameraSample<T> sample = pixelSample(s, r.x0 + i, r.y + j, n);
                    Vec<T> alone;
                    traceCameraSamples(s, &sample, 1, &alone, b);
                    ASSERT_EQ(block[std::size_t(j) * r.count + i], alone)
                        << "pixel " << r.x0 + i << "," << r.y + j << " sample " << n << " of rows "
                        << r.y << " to " << r.y + r.rows - 1;
                }
            EXPECT_EQ(a.total(), b.total());
        }
}

// The renderer's block path (traceCameraBlock: a pixel's samples side by side
// in a packet) gives, lane for lane, what the list path gives for each pixel
// and sample: blocks that start mid-pattern, of fewer samples than a packet
// has lanes and of more, on pixels that are not a multiple of any packet
// width, in both precisions and with both kinds of sample.
template <typename T>
void checkBlockMatchesList(int samplesPerPixel, int n0, int samples, bool openEnded) {
    Scene scene;
    scene.camera = Camera{{0, 0.35, -1}, {0, 0.25, 0}, {0, 1, 0}, 73.74};
    scene.render.width = 37;
    scene.render.height = 4;
    scene.render.samplesPerPixel = samplesPerPixel;
    scene.materials = {Material{"glass", {0, 0, 0}, 1, 200, 0.1, 0.9, 1.5, std::nullopt},
                       Material{"m", {0.5, 0.2, 0.1}, 1, 50, 0.5, 0, 1.5, Checker{{0, 0, 0}, 0.5}}};
    scene.lights = {Light{"key", {5, 5, -10}, {1, 1, 1}, 1}};
    scene.spheres = {Sphere{"ball", {0, 0.2, 2}, 0.6, "glass"},
                     Sphere{"floor", {0, -99999.5, 0}, 99999, "m"}};
    PreparedScene<T> s = prepareScene<T>(scene);
    s.openEndedSamples = openEnded;
    const int x0 = 3, pixels = 29;
    for (int y = 0; y < scene.render.height; ++y) {
        std::vector<Vec<T>> block(std::size_t(pixels) * samples), list(block.size());
        std::vector<CameraSample<T>> listed;
        for (int p = 0; p < pixels; ++p)
            for (int k = 0; k < samples; ++k) listed.push_back(pixelSample(s, x0 + p, y, n0 + k));
        RayCounts a, b;
        traceCameraBlock(s, y, x0, pixels, n0, samples, block.data(), a);
        traceCameraSamples(s, listed.data(), int(listed.size()), list.data(), b);
        for (std::size_t q = 0; q < block.size(); ++q)
            ASSERT_EQ(block[q], list[q])
                << "pixel " << x0 + q / samples << "," << y << " sample " << n0 + q % samples;
        EXPECT_EQ(a.total(), b.total());
        EXPECT_EQ(a.camera, std::uint64_t(pixels) * samples);
    }
}

// Under every kernel: packets of 2 to 16 lanes, which a block's samples fill
// whole, in part, or across pixels.
TEST(RayPacket, CameraBlockEqualsSampleList) {
    test::forEveryKernel([](const std::string&) {
        checkBlockMatchesList<float>(64, 5, 6, false);
        checkBlockMatchesList<double>(64, 5, 6, false);
        checkBlockMatchesList<float>(64, 0, 33, false);
        checkBlockMatchesList<float>(1024, 16, 16, true);
        checkBlockMatchesList<double>(1024, 7, 33, true);
        checkBlockMatchesList<float>(1024, 0, 2, true);
    });
}

TEST(RayPacket, CameraRowEqualsSampleList) {
    checkRowMatchesList<float>(1);
    checkRowMatchesList<float>(5);
    checkRowMatchesList<double>(1);
    checkRowMatchesList<double>(5);
    checkRowMatchesList<float>(33, true);
    checkRowMatchesList<double>(33, true);
}

// Where a packet's refracted and reflected rays fit in one packet they are
// traced as one (tracer_kernel.cpp, traceBranches()); with per-level shares
// (traceCameraRowAtDepths) each is traced alone. Both give each ray the same
// radiance bit for bit, deep among glass and mirror balls where few lanes are
// left, under every kernel (packets of 2 to 16 lanes), in both precisions.
template <typename T>
void checkBranchesTogetherMatchAlone() {
    Scene scene;
    scene.camera = Camera{{0, 0.6, -2.5}, {0, 0.3, 0}, {0, 1, 0}, 60};
    scene.render.width = 45;
    scene.render.height = 12;
    scene.render.maxDepth = 10;
    scene.materials = {Material{"glass", {0, 0, 0}, 1, 200, 0.1, 0.9, 1.5, std::nullopt},
                       Material{"mirror", {0.1, 0.1, 0.1}, 1, 200, 0.8, 0, 1.5, std::nullopt},
                       Material{"m", {0.5, 0.2, 0.1}, 1, 50, 0.5, 0, 1.5, Checker{{0, 0, 0}, 0.5}}};
    scene.lights = {Light{"key", {5, 5, -10}, {1, 1, 1}, 1}};
    scene.spheres = {
        Sphere{"a", {-0.7, 0.3, 1}, 0.45, "glass"}, Sphere{"b", {0, 0.3, 1.3}, 0.45, "glass"},
        Sphere{"c", {0.7, 0.3, 1}, 0.45, "mirror"}, Sphere{"d", {0, 0.9, 2.2}, 0.5, "glass"},
        Sphere{"floor", {0, -99999.5, 0}, 99999, "m"}};
    const PreparedScene<T> s = prepareScene<T>(scene);
    const int depth = scene.render.maxDepth;
    std::uint64_t refracted = 0;
    for (int y = 0; y < scene.render.height; ++y) {
        std::vector<Vec<T>> together(scene.render.width), alone(scene.render.width),
            atDepth(scene.render.width);
        RayCounts a, b;
        traceCameraRow(s, y, 0, scene.render.width, 0, together.data(), a);
        traceCameraRowAtDepths(s, y, 0, scene.render.width, 0, alone.data(), &depth, 1,
                               atDepth.data(), b);
        for (int x = 0; x < scene.render.width; ++x)
            ASSERT_EQ(together[x], alone[x]) << "pixel " << x << "," << y;
        EXPECT_EQ(a.total(), b.total());
        EXPECT_EQ(a.refraction, b.refraction);
        refracted += a.refraction;
    }
    EXPECT_GT(refracted, 0u);  // the rows do go through the glass
}

TEST(RayPacket, BranchesTracedTogetherEqualBranchesTracedAlone) {
    test::forEveryKernel([](const std::string&) {
        checkBranchesTogetherMatchAlone<float>();
        checkBranchesTogetherMatchAlone<double>();
    });
}

// The seed floor's centre relative to its camera, -99999.85, is 0.0015625 off
// in float; the set keeps that as the low term, so the sphere is the double
// scene's. (GCC 12 once optimised the low term away; see SphereSet::split.)
TEST(RayPacket, TwoTermCentreKeepsWhatFloatDrops) {
    SphereSet<float> s;
    s.add(glm::dvec3(0.0, -99999.85, 1.0), glm::dvec3(0.0, 5.8e-12, 0.0), 99999.0,
          Vec<float>(0.0f));
    EXPECT_EQ(s.centre[0].y, -99999.8515625f);
    EXPECT_NEAR(double(s.centre[0].y) + double(s.centreLo[0].y), -99999.85, 1e-9);
    EXPECT_EQ(s.centreLo[0].x, 0.0f);
    // c = |camera - centre|^2 - r^2 = 99999.85^2 - 99999^2 = 170000.0225
    EXPECT_NEAR(s.cameraC[0], 170000.0225, 0.02);
}

// Preparing a scene gives each sphere the camera term the scalar function
// gives it, bit for bit, though many are computed a SIMD vector at a time:
// spheres near and far, tiny and huge (the seed's floor scaled by 1e4), a
// count that leaves a remainder beside the vectors.
template <typename T>
void expectCameraTermsLikeTheScalarOnes() {
    Scene scene = test::seedScene();
    std::mt19937 rng(71);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int k = 0; k < 203; ++k) {
        const double scale = std::pow(10.0, 4 * unit(rng));
        Sphere sp = scene.spheres[0];
        sp.name = "ball " + std::to_string(k);
        sp.center = Vec3{unit(rng), unit(rng), unit(rng)} * (10 * scale);
        sp.radius = scale * (0.01 + std::abs(unit(rng)));
        scene.spheres.push_back(sp);
    }
    scene.spheres[3].center *= 1e4;
    scene.spheres[3].radius *= 1e4;
    const PreparedScene<T> s = prepareScene<T>(scene);
    for (int k = 0; k < s.spheres.count(); ++k) {
        const T scalar =
            accurateOffsetSquared(s.camera.origin, s.spheres.centre[k], s.spheres.centreLo[k],
                                  s.spheres.rrHi[k], s.spheres.rrLo[k]);
        ASSERT_EQ(std::memcmp(&s.spheres.cameraC[k], &scalar, sizeof scalar), 0)
            << "sphere " << k << ": " << s.spheres.cameraC[k] << " against " << scalar;
    }
}

TEST(RayPacket, PreparedCameraTermsEqualTheScalarOnes) {
    expectCameraTermsLikeTheScalarOnes<float>();
    expectCameraTermsLikeTheScalarOnes<double>();
}

}  // namespace
}  // namespace whitted
