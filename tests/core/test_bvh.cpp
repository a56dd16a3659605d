// Tests for core/bvh.* and core/tracer/bvh_traverse.h: the tree holds every sphere
// once inside nested boxes, and rays traced through it find exactly what brute
// force finds, down to the last bit of every pixel, in float and double.
// Random cases print their seed; WHITTED_TEST_SEED replays one.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "field_layouts.h"
#include "support/core_support.h"
#include "support/test_support.h"
#include "tracer/bvh.h"
#include "tracer/bvh_split.h"
#include "tracer/bvh_traverse.h"
#include "tracer/renderer.h"
#include "tracer/tracer.h"

namespace whitted {
namespace {

static_assert(sizeof(BvhNode) == 32, "a node is 32 bytes, in float and double trees");

std::uint32_t testSeed(std::uint32_t fallback) {
    const char* s = std::getenv("WHITTED_TEST_SEED");
    return s ? static_cast<std::uint32_t>(std::strtoul(s, nullptr, 10)) : fallback;
}

// Kinds of random scene, each an extreme the tree's boxes must survive.
enum class Layout { Field, Overlapping, Nested, Far, Tiny };

const char* layoutName(Layout l) {
    switch (l) {
        case Layout::Field:
            return "field";
        case Layout::Overlapping:
            return "overlapping";
        case Layout::Nested:
            return "nested";
        case Layout::Far:
            return "far";
        case Layout::Tiny:
            return "tiny";
    }
    return "?";
}

// Two samples of each pixel, so that the jittered second one is compared too.
constexpr int kSamplesPerPixel = 2;

// `count` random spheres of the layout, the seed's checker floor among them
// (a random index), matte, mirror and glass materials, two lights.
Scene randomScene(int count, Layout layout, std::uint32_t seed, bool floor) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Scene s;
    s.render = {64, 48, 4, kSamplesPerPixel, Precision::Float};
    s.background = {0.02, 0.03, 0.05};
    auto material = [](const char* name, Vec3 diffuse, double ks, double n, double kr, double kt,
                       double ior) { return Material{name, diffuse, ks, n, kr, kt, ior, {}}; };
    const Material matte = material("matte", {0.7, 0.3, 0.2}, 0.5, 20, 0, 0, 1.5);
    const Material mirror = material("mirror", {0.1, 0.1, 0.1}, 1, 60, 0.8, 0, 1.5);
    const Material glass = material("glass", {0, 0, 0}, 1, 200, 0.1, 0.9, 1.5);
    const Material haze = material("haze", {0.2, 0.5, 0.2}, 0, 50, 0, 0.5, 1.1);
    Material checker = material("floor", {0.75, 0.75, 0.75}, 1, 50, 0.25, 0, 1.5);
    checker.checker = Checker{{0, 0, 0}, 0.5};
    s.materials = {matte, mirror, glass, haze, checker};
    const char* kinds[] = {"matte", "mirror", "glass", "haze"};
    double scale = 1.0, extent = 4.0 + std::cbrt(double(count));
    Vec3 centre{0, 0, 6 + extent};
    if (layout == Layout::Far) centre = {1e6, 1e6 + 3, 1e6 + 7};
    if (layout == Layout::Tiny) scale = 1e-3;
    s.camera.position = layout == Layout::Far ? Vec3{1e6, 1e6 + 3, 1e6 + 7 - 2 * extent - 6}
                                              : Vec3{0, 1, 0} * scale;
    s.camera.lookAt = centre * (layout == Layout::Tiny ? scale : 1.0);
    s.camera.vfovDegrees = 60;
    s.lights = {{"key", s.camera.position + Vec3{5, 8, -4} * scale, {1, 1, 1}, 0.8},
                {"fill",
                 centre * (layout == Layout::Tiny ? scale : 1.0) + Vec3{-6, 3, 0} * scale,
                 {0.4, 0.5, 1},
                 0.6}};
    const int floorAt = floor ? static_cast<int>(u(rng) * count) : -1;
    for (int i = 0; i < count; ++i) {
        Sphere sp;
        // insert(), not "s" + to_string(i): GCC 12 at -O3 warns of a
        // (false) overflow in the inlined prepend (-Wstringop-overflow).
        sp.name = std::to_string(i).insert(0, 1, 's');
        sp.material = kinds[static_cast<int>(u(rng) * 4) % 4];
        Vec3 p{(u(rng) - 0.5) * 2 * extent, (u(rng) - 0.5) * extent, (u(rng) - 0.5) * 2 * extent};
        double r = extent / std::cbrt(double(count)) * (0.1 + 0.5 * u(rng));
        if (layout == Layout::Overlapping) r *= 3;
        if (layout == Layout::Nested && i > 0 && u(rng) < 0.7) {
            const Sphere& outer = s.spheres[static_cast<int>(u(rng) * i)];
            p = (outer.center - centre * (layout == Layout::Tiny ? scale : 1.0)) / scale;
            r = outer.radius / scale * (0.3 + 0.65 * u(rng));
            if (u(rng) < 0.2) r = outer.radius / scale;  // the same sphere twice
        }
        if (layout == Layout::Tiny && u(rng) < 0.5) r = 1e-4 / scale * (1 + u(rng));
        sp.center = (layout == Layout::Tiny ? centre * scale : centre) + p * scale;
        sp.radius = r * scale;
        if (layout == Layout::Tiny) sp.radius = std::max(sp.radius, 1e-7);
        if (i == floorAt) {
            sp.material = "floor";
            sp.radius = 99999 * scale;
            sp.center = Vec3{0, -99999.5 - extent * 0.5, 0} * scale +
                        (layout == Layout::Far ? centre : Vec3{0.0});
        }
        s.spheres.push_back(sp);
    }
    return s;
}

// Every sample of every pixel (of every `rowStep`th row), traced with and
// without the tree: the radiance must agree to the bit.
template <typename T>
void expectSameSamples(const Scene& scene, const std::string& what, int rowStep = 1) {
    useAcceleration(Acceleration::bruteForce);
    const PreparedScene<T> brute = prepareScene<T>(scene);
    useAcceleration(Acceleration::bvh);
    const PreparedScene<T> tree = prepareScene<T>(scene);
    useAcceleration(Acceleration::automatic);
    ASSERT_FALSE(brute.useBvh);
    ASSERT_TRUE(tree.useBvh);
    const int w = scene.render.width;
    std::vector<Vec<T>> a(w), b(w);
    int differing = 0, background = 0;
    for (int n = 0; n < scene.render.samplesPerPixel; ++n) {
        for (int y = 0; y < scene.render.height; y += rowStep) {
            RayCounts ca, cb;
            traceCameraRow(brute, y, 0, w, n, a.data(), ca);
            traceCameraRow(tree, y, 0, w, n, b.data(), cb);
            for (int x = 0; x < w; ++x) {
                background += a[x] == brute.background;
                if (std::memcmp(&a[x], &b[x], sizeof(Vec<T>)) == 0) continue;
                if (differing++ < 5)
                    ADD_FAILURE() << what << ": pixel (" << x << ", " << y << ") sample " << n
                                  << ": brute (" << a[x].x << ", " << a[x].y << ", " << a[x].z
                                  << ") tree (" << b[x].x << ", " << b[x].y << ", " << b[x].z
                                  << ")";
            }
            EXPECT_EQ(ca.total(), cb.total()) << what << ": row " << y << " traced other rays";
        }
    }
    EXPECT_EQ(differing, 0) << what;
    // A test of something: the spheres cover much of the picture.
    const int rows = (scene.render.height + rowStep - 1) / rowStep;
    const int samples = w * rows * scene.render.samplesPerPixel;
    std::printf("%s: %.0f %% background\n", what.c_str(), 100.0 * background / samples);
}

// The renderer's image (threads, tiles, sample sums) with and without the tree.
void expectSameImage(const Scene& scene, const std::string& what) {
    RenderOptions options;
    options.threads = 2;
    options.progressive = false;
    useAcceleration(Acceleration::bruteForce);
    const RenderResult brute = render(scene, options);
    useAcceleration(Acceleration::bvh);
    const RenderResult tree = render(scene, options);
    useAcceleration(Acceleration::automatic);
    ASSERT_EQ(brute.image.rgb.size(), tree.image.rgb.size());
    EXPECT_EQ(std::memcmp(brute.image.rgb.data(), tree.image.rgb.data(),
                          brute.image.rgb.size() * sizeof(float)),
              0)
        << what;
}

// One random scene traced both ways, every sample compared, in float and double.
void expectSameRenders(int count, Layout layout, bool floor, std::uint32_t sceneSeed,
                       int samplesPerPixel = kSamplesPerPixel, int rowStep = 1) {
    Scene scene = randomScene(count, layout, sceneSeed, floor);
    scene.render.samplesPerPixel = samplesPerPixel;
    const std::string what = std::to_string(count) + " spheres, " + layoutName(layout) +
                             (floor ? ", floor" : "") + ", scene seed " + std::to_string(sceneSeed);
    expectSameSamples<float>(scene, what + ", float", rowStep);
    expectSameSamples<double>(scene, what + ", double", rowStep);
}

// Under the sanitizers one sample of every pixel of every second row of a
// large field (500 spheres and more) walks the same deep trees from edge to
// edge of the picture (what they check is memory, not the other samples'
// jitter, which Release compares): the six fields of 5000 took 80 s of the
// ASan stage's CPU with every sample, 34 s with one a pixel.
constexpr int kLargeSamplesPerPixel = test::kSanitized ? 1 : kSamplesPerPixel;
constexpr int kLargeRowStep = test::kSanitized ? 2 : 1;

class BvhRendersLikeBruteForce : public ::testing::TestWithParam<int> {};

TEST_P(BvhRendersLikeBruteForce, EveryPixelEqualInFloatAndDouble) {
    const int count = GetParam();
    const std::uint32_t seed = testSeed(1000 + count);
    std::printf("seed %u (WHITTED_TEST_SEED replays it)\n", seed);
    const bool large = count >= 500;
    int variant = 0;
    for (Layout layout :
         {Layout::Field, Layout::Overlapping, Layout::Nested, Layout::Far, Layout::Tiny})
        for (bool floor : {true, false})
            expectSameRenders(count, layout, floor, seed * 31 + variant++,
                              large ? kLargeSamplesPerPixel : kSamplesPerPixel,
                              large ? kLargeRowStep : 1);
}

INSTANTIATE_TEST_SUITE_P(Counts, BvhRendersLikeBruteForce, ::testing::Values(1, 2, 7, 50, 500));

// 5000 spheres, each layout a test of its own: together they took 20 s in
// Release, which the sanitizer builds (3 to 6 times slower) would take past
// CTest's 120 s limit. Without a floor only the field: the others add nothing
// the 500-sphere case does not test, at a brute-force cost of minutes.
class BvhRendersLikeBruteForceLarge : public ::testing::TestWithParam<std::tuple<Layout, bool>> {};

TEST_P(BvhRendersLikeBruteForceLarge, EveryPixelEqualInFloatAndDouble) {
    const auto [layout, floor] = GetParam();
    const std::uint32_t seed =
        testSeed(5000) * 31 + static_cast<std::uint32_t>(layout) * 2 + (floor ? 1 : 0);
    std::printf("seed %u (WHITTED_TEST_SEED replays it)\n", seed);
    expectSameRenders(5000, layout, floor, seed, kLargeSamplesPerPixel, kLargeRowStep);
}

INSTANTIATE_TEST_SUITE_P(
    Count5000, BvhRendersLikeBruteForceLarge,
    ::testing::Values(std::tuple{Layout::Field, true}, std::tuple{Layout::Field, false},
                      std::tuple{Layout::Overlapping, true}, std::tuple{Layout::Nested, true},
                      std::tuple{Layout::Far, true}, std::tuple{Layout::Tiny, true}),
    [](const auto& info) {
        return std::string(layoutName(std::get<0>(info.param))) +
               (std::get<1>(info.param) ? "_floor" : "_noFloor");
    });

// whitted-field's layouts (the ones docs/design/acceleration.md times against Embree),
// small: clumps, radii over three decades, mostly glass or mirrors, the camera
// inside or above, each traced with and without the tree.
class FieldLayoutRendersLikeBruteForce : public ::testing::TestWithParam<FieldLayout> {};

TEST_P(FieldLayoutRendersLikeBruteForce, EveryPixelEqualInFloatAndDouble) {
    const std::string& name = GetParam().name;
    Scene scene = sphereField(*fieldLayout(name, 1500), 96, 54);
    scene.render.samplesPerPixel = kLargeSamplesPerPixel;
    expectSameSamples<float>(scene, name + ", float");
    expectSameSamples<double>(scene, name + ", double");
}

INSTANTIATE_TEST_SUITE_P(Count1500, FieldLayoutRendersLikeBruteForce,
                         ::testing::ValuesIn(fieldLayouts()),
                         [](const auto& info) { return info.param.name; });

TEST(BvhRendersLikeBruteForceImage, RendererImagesEqual) {
    for (Precision p : {Precision::Float, Precision::Double}) {
        Scene scene = randomScene(300, Layout::Nested, testSeed(77), true);
        scene.render.precision = p;
        expectSameImage(scene, std::string("300 nested, ") + std::string(precisionName(p)));
    }
}

// Every kernel (baseline SSE2 to AVX-512: packets of 2 to 16 lanes) traverses
// the tree to the brute-force image.
TEST(BvhRendersLikeBruteForceImage, EveryKernel) {
    const std::uint32_t seed = testSeed(2024);
    std::printf("seed %u\n", seed);
    const Scene scene = randomScene(400, Layout::Overlapping, seed, true);
    test::forEveryKernel([&](const std::string& kernel) {
        expectSameSamples<float>(scene, "kernel " + kernel + ", float");
        expectSameSamples<double>(scene, "kernel " + kernel + ", double");
    });
}

// The spheres' centres and radii, as the build takes them.
std::pair<std::vector<glm::dvec3>, std::vector<double>> geometryOf(const Scene& scene) {
    std::vector<glm::dvec3> centres;
    std::vector<double> radii;
    for (const Sphere& sp : scene.spheres) {
        centres.push_back(sp.center);
        radii.push_back(sp.radius);
    }
    return {centres, radii};
}

// Build checks on the tree's own invariants.
// The sphere indices of a tree's leaves, leaf after leaf.
template <typename T>
std::vector<int> leafIndices(const SphereBvh<T>& bvh) {
    std::vector<int> indices;
    for (const LeafSphere<T>& sphere : bvh.leafSpheres) indices.push_back(sphere.index);
    return indices;
}

template <typename T>
void expectWellFormed(const std::vector<glm::dvec3>& centres, const std::vector<double>& radii,
                      const SphereBvh<T>& bvh) {
    const int n = static_cast<int>(radii.size());
    std::vector<int> seen(n, 0);
    for (int k : bvh.direct) ++seen[k];
    for (const LeafSphere<T>& sphere : bvh.leafSpheres) ++seen[sphere.index];
    for (int i = 0; i < n; ++i) ASSERT_EQ(seen[i], 1) << "sphere " << i;
    EXPECT_LE(bvh.depth, kMaxBvhDepth);
    int leafSpheres = 0;
    std::vector<int> parents(bvh.nodes.size(), -1);
    if (!bvh.nodes.empty()) {
        EXPECT_EQ(bvh.nodes.at(1).count, 0) << "nodes[1] pads the root";
    }
    for (int i = 0; i < static_cast<int>(bvh.nodes.size()); ++i) {
        const BvhNode& node = bvh.nodes[i];
        if (i == 1) continue;
        for (int a = 0; a < 3; ++a) ASSERT_LE(node.lo[a], node.hi[a]) << "node " << i;
        if (node.count > 0) {
            leafSpheres += node.count;
            constexpr float kInf = std::numeric_limits<float>::infinity();
            glm::dvec3 lowest(kInf), highest(-kInf);
            for (int j = node.first; j < node.first + node.count; ++j) {
                const int k = bvh.leafSpheres[j].index;
                for (int a = 0; a < 3; ++a) {
                    EXPECT_LE(double(node.lo[a]), centres[k][a] - radii[k]) << "sphere " << k;
                    EXPECT_GE(double(node.hi[a]), centres[k][a] + radii[k]) << "sphere " << k;
                    lowest[a] = std::min(lowest[a], centres[k][a] - radii[k]);
                    highest[a] = std::max(highest[a], centres[k][a] + radii[k]);
                }
            }
            // No looser than rounding outward makes it: one float step more
            // would hold a sphere less.
            for (int a = 0; a < 3; ++a) {
                EXPECT_GT(double(std::nextafter(node.lo[a], kInf)), lowest[a]) << "leaf " << i;
                EXPECT_LT(double(std::nextafter(node.hi[a], -kInf)), highest[a]) << "leaf " << i;
            }
            continue;
        }
        ASSERT_GE(node.count, -3);
        ASSERT_LT(node.count, 0) << "node " << i;
        EXPECT_EQ(node.first % 2, 0) << "the children of node " << i << " share a cache line";
        for (int c = node.first; c < node.first + 2; ++c) {
            ASSERT_LT(c, static_cast<int>(bvh.nodes.size()));
            ASSERT_EQ(parents[c], -1) << "node " << c << " has two parents";
            parents[c] = i;
            for (int a = 0; a < 3; ++a) {
                EXPECT_LE(node.lo[a], bvh.nodes[c].lo[a]) << "child " << c << " of " << i;
                EXPECT_GE(node.hi[a], bvh.nodes[c].hi[a]) << "child " << c << " of " << i;
            }
        }
    }
    EXPECT_EQ(leafSpheres, static_cast<int>(bvh.leafSpheres.size()));
}

TEST(BvhBuild, EverySphereInOneLeafInsideNestedBoxes) {
    const std::uint32_t seed = testSeed(4242);
    std::printf("seed %u\n", seed);
    for (int count : {1, 2, 7, 50, 500, 5000, 20000}) {
        for (Layout layout :
             {Layout::Field, Layout::Overlapping, Layout::Nested, Layout::Far, Layout::Tiny}) {
            const Scene scene = randomScene(count, layout, seed + count, true);
            const auto [centres, radii] = geometryOf(scene);
            SCOPED_TRACE(std::to_string(count) + " " + layoutName(layout));
            expectWellFormed(centres, radii, buildSphereBvh<float>(centres, radii));
            expectWellFormed(centres, radii, buildSphereBvh<double>(centres, radii));
        }
    }
}

// The build splits its top levels and then its lower ranges on all threads;
// the tree must not depend on how many there are (so a render's speed does not
// either), and sphere indices past 65535 (which the build stores in two halves)
// must come back whole.
TEST(BvhBuild, SameTreeOnAnyNumberOfThreads) {
    const Scene scene = randomScene(70000, Layout::Overlapping, testSeed(77), true);
    auto [centres, radii] = geometryOf(scene);
    BvhBuildOptions one;
    one.threads = 1;
    const SphereBvh<float> alone = buildSphereBvh<float>(centres, radii, one);
    expectWellFormed(centres, radii, alone);
    for (int threads : {2, 3, 8}) {
        BvhBuildOptions many;
        many.threads = threads;
        const SphereBvh<float> tree = buildSphereBvh<float>(centres, radii, many);
        ASSERT_EQ(tree.nodes.size(), alone.nodes.size()) << threads << " threads";
        for (std::size_t i = 0; i < tree.nodes.size(); ++i)
            ASSERT_EQ(std::memcmp(&tree.nodes[i], &alone.nodes[i], sizeof(BvhNode)), 0)
                << "node " << i << ", " << threads << " threads";
        EXPECT_EQ(leafIndices(tree), leafIndices(alone)) << threads << " threads";
        EXPECT_EQ(tree.direct, alone.direct) << threads << " threads";
    }
}

// The build's partition puts a split's first child's refs first, whatever
// the range's size against its blocks of 64 (none, one, both ends' blocks and
// the rest between them) and however few refs go to either side.
TEST(BvhBuild, PartitionPutsTheFirstChildsRefsFirst) {
    using namespace bvh_build;
    std::mt19937 rng(testSeed(31));
    std::uniform_real_distribution<float> coordinate(-10.0f, 10.0f);
    for (int count : {0, 1, 2, 63, 64, 127, 128, 129, 130, 191, 192, 193, 257, 1000, 4099}) {
        std::vector<Ref<float>> refs;
        for (int i = 0; i < count; ++i) {
            const Lanes<float> c{coordinate(rng), coordinate(rng), coordinate(rng), 0};
            refs.emplace_back(c - 0.1f, c + 0.1f, 70000 + i);
        }
        LaneBox<float> centres;
        for (const Ref<float>& r : refs) centres.grow(r.centre2(), r.centre2());
        const Binning<float> map(16, centres);
        for (int bin = -1; bin < 16; ++bin) {  // -1: nothing first; 15: everything
            const Split split{0, bin, 0.0};
            std::vector<Ref<float>> parted = refs;
            const int first = partitionRefs(parted.data(), count, map, split);
            SCOPED_TRACE(std::to_string(count) + " refs, bin " + std::to_string(bin));
            int expected = 0;
            for (const Ref<float>& r : refs) expected += inFirstChild(r, map, split);
            ASSERT_EQ(first, expected);
            for (int i = 0; i < count; ++i)
                ASSERT_EQ(inFirstChild(parted[i], map, split), i < first) << "ref " << i;
            std::vector<int> before, after;
            for (int i = 0; i < count; ++i) {
                before.push_back(refs[i].sphere());
                after.push_back(parted[i].sphere());
            }
            std::sort(after.begin(), after.end());
            EXPECT_EQ(after, before) << "every ref once";
        }
    }
}

// A render without a kept tree builds its subtrees as rays first enter them
// (BvhBuildOptions::lazy), on whichever thread gets there first: the picture
// must be the whole tree's, bit for bit, on any number of threads.
TEST(BvhLazy, RendersTheWholeTreesImageOnAnyNumberOfThreads) {
    for (const Precision precision : {Precision::Float, Precision::Double}) {
        Scene scene = randomScene(20000, Layout::Field, testSeed(88), true);
        scene.render.precision = precision;
        scene.render.samplesPerPixel = 1;
        scene.render.width = 128;
        scene.render.height = 96;
        // One, two and three threads between the two precisions, and a small
        // picture: under ThreadSanitizer this test took 66 s of its 120 alone
        // on the machine, and CI runs two tests at once.
        for (int threads : precision == Precision::Float ? std::vector{1, 3} : std::vector{2}) {
            SCOPED_TRACE(std::string(precisionName(precision)) + ", " + std::to_string(threads) +
                         " threads");
            RenderOptions options;
            options.threads = threads;
            options.progressive = false;
            const RenderResult lazy = render(scene, options);
            BvhCache cache;  // a kept tree is built whole
            options.bvhCache = &cache;
            const RenderResult whole = render(scene, options);
            ASSERT_EQ(cache.builds, 1);
            ASSERT_EQ(lazy.image.rgb.size(), whole.image.rgb.size());
            EXPECT_EQ(std::memcmp(lazy.image.rgb.data(), whole.image.rgb.data(),
                                  lazy.image.rgb.size() * sizeof(float)),
                      0);
        }
    }
}

// A camera that sees a small part of the scene builds few of its subtrees,
// and the rays it traces find what the whole tree's find.
TEST(BvhLazy, BuildsOnlyTheSubtreesRaysEnter) {
    // Balls close enough that a ray stops at the first few, lit from beside
    // the camera: the shadow rays go back the way the camera's came.
    Scene scene = randomScene(20000, Layout::Overlapping, testSeed(89), false);
    scene.lights.resize(1);
    scene.camera.vfovDegrees = 4;
    scene.render.width = 48;
    scene.render.height = 48;
    scene.render.samplesPerPixel = 1;
    const PreparedScene<float> lazy = prepareScene<float>(scene);
    ASSERT_TRUE(lazy.bvh && lazy.bvh->lazy);
    const int jobs = lazyJobCount(*lazy.bvh);
    EXPECT_GE(jobs, 8);
    EXPECT_EQ(lazyJobsBuilt(*lazy.bvh), 0) << "nothing is built before a ray needs it";
    BvhCache cache;
    const PreparedScene<float> whole = prepareScene<float>(scene, &cache);
    ASSERT_FALSE(whole.bvh->lazy);
    std::vector<Vec<float>> a(48), b(48);
    for (int y = 0; y < 48; ++y) {
        RayCounts ca, cb;
        traceCameraRow(lazy, y, 0, 48, 0, a.data(), ca);
        traceCameraRow(whole, y, 0, 48, 0, b.data(), cb);
        ASSERT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec<float>)), 0) << "row " << y;
    }
    std::printf("%d of %d subtrees built\n", lazyJobsBuilt(*lazy.bvh), jobs);
    EXPECT_GT(lazyJobsBuilt(*lazy.bvh), 0);
    EXPECT_LE(lazyJobsBuilt(*lazy.bvh), jobs / 2);
}

// A render on two threads, in one pass, that keeps its tree in `cache`.
RenderOptions keepingTheTreeIn(BvhCache& cache) {
    RenderOptions options;
    options.threads = 2;
    options.progressive = false;
    options.bvhCache = &cache;
    return options;
}

// The picture `image` is the brute-force render of `scene`, bit for bit.
::testing::AssertionResult isBruteForcePicture(const Scene& scene, const Image& image) {
    useAcceleration(Acceleration::bruteForce);
    const RenderResult brute = render(scene, RenderOptions{2, 32, false});
    useAcceleration(Acceleration::automatic);
    if (brute.image.rgb.size() != image.rgb.size())
        return ::testing::AssertionFailure() << "another size";
    if (std::memcmp(brute.image.rgb.data(), image.rgb.data(), image.rgb.size() * sizeof(float)))
        return ::testing::AssertionFailure() << "pixels differ from the brute-force render";
    return ::testing::AssertionSuccess();
}

// After an edit that moves a few spheres or the camera (it
// moves every sphere of the camera-centred frame), the render refits the kept
// tree instead of building one, and the picture is still
// the brute-force one, bit for bit; a refit that wears the tree out (one ball grown huge) builds.
TEST(BvhRefit, MovedSpheresAndCameraRenderLikeBruteForce) {
    for (const Precision precision : {Precision::Float, Precision::Double}) {
        Scene scene = randomScene(600, Layout::Field, testSeed(61), true);
        scene.render.precision = precision;
        BvhCache cache;
        const RenderOptions options = keepingTheTreeIn(cache);
        render(scene, options);
        ASSERT_EQ(cache.builds, 1);
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> step(-0.7, 0.7);
        // Edits 0 and 2 move a few balls, edit 1 also the camera.
        for (int edit = 0; edit < 3; ++edit) {
            for (int k = 0; k < 20; ++k) {
                Sphere& sp = scene.spheres[rng() % (scene.spheres.size() - 1)];
                sp.center += Vec3{3 * step(rng), step(rng), 3 * step(rng)};
                sp.radius *= 1.0 + 0.2 * step(rng);
            }
            if (edit == 1) scene.camera.position.x += 0.3;
            const RenderResult refit = render(scene, options);
            EXPECT_EQ(cache.builds, 1) << "edit " << edit;
            EXPECT_EQ(cache.refits, edit + 1) << "edit " << edit;
            EXPECT_TRUE(isBruteForcePicture(scene, refit.image)) << "edit " << edit;
        }
        scene.spheres[5].radius = 40;  // its boxes now cover the field
        render(scene, options);
        EXPECT_EQ(cache.builds, 2) << "a worn-out tree is built anew";
    }
}

// With the caller's geometry revision unchanged, a render uses the kept tree as
// it is, and the picture is the brute-force one bit for bit: new materials
// show. A camera move to another frame, or a new revision, refits.
TEST(BvhReuse, SameGeometryRevision_UsesTheTreeAsItIs_NewMaterialsShow) {
    for (const Precision precision : {Precision::Float, Precision::Double}) {
        SCOPED_TRACE(precisionName(precision));
        Scene scene = randomScene(600, Layout::Field, testSeed(64), true);
        scene.render.precision = precision;
        BvhCache cache;
        cache.geometryRevision = 7;
        const RenderOptions options = keepingTheTreeIn(cache);
        render(scene, options);
        ASSERT_EQ(cache.builds, 1);
        auto expectBruteForcePicture = [&](const char* edit) {
            EXPECT_TRUE(isBruteForcePicture(scene, render(scene, options).image)) << edit;
        };
        // Half the balls take another material: nothing moved.
        for (std::size_t i = 0; i + 1 < scene.spheres.size(); i += 2)
            scene.spheres[i].material = scene.materials[i % scene.materials.size()].name;
        expectBruteForcePicture("materials");
        EXPECT_EQ(cache.reuses, 1);
        EXPECT_EQ(cache.refits, 0);
        // The camera moved far enough to take the centres in another frame.
        scene.camera.position.x += 0.5;
        expectBruteForcePicture("camera");
        EXPECT_EQ(cache.reuses, 1);
        EXPECT_EQ(cache.refits, 1);
        // A ball moved, and the caller says so.
        scene.spheres[3].center.y += 0.4;
        cache.geometryRevision = 8;
        expectBruteForcePicture("moved");
        EXPECT_EQ(cache.reuses, 1);
        EXPECT_EQ(cache.refits, 2);
        EXPECT_EQ(cache.builds, 1);
    }
}

// The centres and radii of `scene` as the tree holds them: in the frame at `origin`.
std::pair<std::vector<glm::dvec3>, std::vector<double>> geometryInFrame(const Scene& scene,
                                                                        const glm::dvec3& origin) {
    auto [centres, radii] = geometryOf(scene);
    for (glm::dvec3& c : centres) c -= origin;
    return {centres, radii};
}

// An edit of a few spheres refits only their leaves and the nodes above them,
// and refills only their leaves' copies while the eye stays: the kept tree is
// still the built one refit whole, box for box and bit for bit, and every
// leaf's copy is its prepared sphere's. Then the eye moves: every copy follows.
template <typename T>
void expectRefitOfFewLikeAWholeRefit() {
    Scene scene = randomScene(3000, Layout::Field, testSeed(65), true);
    BvhCache cache;
    cache.geometryRevision = 1;
    const glm::dvec3 origin = prepareScene<T>(scene, &cache, 2).frameOrigin;
    const auto [builtCentres, builtRadii] = geometryInFrame(scene, origin);
    SphereBvh<T> whole = buildSphereBvh<T>(builtCentres, builtRadii);
    std::mt19937 rng(testSeed(66));
    std::uniform_real_distribution<double> step(-0.5, 0.5);
    for (int edit = 0; edit < 4; ++edit) {
        SCOPED_TRACE("edit " + std::to_string(edit));
        for (int k = 0; k < 12; ++k) {
            Sphere& sp = scene.spheres[rng() % (scene.spheres.size() - 1)];  // not the floor
            sp.center += Vec3{step(rng), step(rng), step(rng)};
            sp.radius *= 1.0 + 0.2 * step(rng);
        }
        if (edit == 3) scene.camera.position.y += 1e-9;  // the eye moves, in the same frame
        cache.geometryRevision = edit + 2;
        const PreparedScene<T> s = prepareScene<T>(scene, &cache, 2);
        ASSERT_EQ(s.frameOrigin, origin);
        ASSERT_EQ(cache.builds, 1);
        ASSERT_EQ(cache.refits, edit + 1);
        const auto [centres, radii] = geometryInFrame(scene, origin);
        ASSERT_TRUE(refitSphereBvh(whole, centres, radii));
        ASSERT_EQ(s.bvh->nodes.size(), whole.nodes.size());
        for (std::size_t i = 0; i < whole.nodes.size(); ++i)
            ASSERT_EQ(std::memcmp(&s.bvh->nodes[i], &whole.nodes[i], sizeof(BvhNode)), 0)
                << "node " << i;
        for (std::size_t j = 0; j < s.bvh->leafSpheres.size(); ++j) {
            const LeafSphere<T>& kept = s.bvh->leafSpheres[j];
            const LeafSphere<T> prepared = s.spheres.leafSphere(kept.index);
            ASSERT_TRUE(kept.centre == prepared.centre && kept.rrHi == prepared.rrHi &&
                        kept.cameraC == prepared.cameraC)
                << "slot " << j;
        }
    }
}

TEST(BvhRefit, FewMovedSpheres_RefitAndRefilledLikeTheWholeTree) {
    expectRefitOfFewLikeAWholeRefit<float>();
    expectRefitOfFewLikeAWholeRefit<double>();
}

// A refit of spheres that did not move gives the build's boxes bit for bit:
// it rounds each node's box outward once where the build rounded each sphere's,
// which is the same box.
template <typename T>
void expectRefitOfUnmovedSpheresChangesNothing() {
    const Scene scene = randomScene(5000, Layout::Overlapping, testSeed(63), true);
    const auto [centres, radii] = geometryOf(scene);
    SphereBvh<T> bvh = buildSphereBvh<T>(centres, radii);
    const BvhArray<BvhNode> built = bvh.nodes;
    ASSERT_TRUE(refitSphereBvh(bvh, centres, radii));
    ASSERT_EQ(bvh.nodes.size(), built.size());
    for (std::size_t i = 0; i < built.size(); ++i)
        ASSERT_EQ(std::memcmp(&bvh.nodes[i], &built[i], sizeof(BvhNode)), 0) << "node " << i;
}

TEST(BvhRefit, UnmovedSpheresKeepTheBuiltBoxes) {
    expectRefitOfUnmovedSpheresChangesNothing<float>();
    expectRefitOfUnmovedSpheresChangesNothing<double>();
}

// The refit tree is as well formed as a built one for the moved spheres.
TEST(BvhRefit, RefitBoxesHoldTheMovedSpheres) {
    const Scene scene = randomScene(5000, Layout::Overlapping, testSeed(62), true);
    auto [centres, radii] = geometryOf(scene);
    SphereBvh<float> bvh = buildSphereBvh<float>(centres, radii);
    for (std::size_t i = 0; i < centres.size(); i += 3) {
        centres[i] = centres[i] * 1.1 + glm::dvec3(0.5, -0.25, 2.0);
        radii[i] *= 1.5;
    }
    ASSERT_TRUE(refitSphereBvh(bvh, centres, radii));
    expectWellFormed(centres, radii, bvh);
    centres[bvh.leafSpheres[0].index] = glm::dvec3(1e18, 0, 0);  // beyond what float boxes may hold
    const BvhNode root = bvh.nodes[0];
    EXPECT_FALSE(refitSphereBvh(bvh, centres, radii));
    EXPECT_EQ(std::memcmp(&root, &bvh.nodes[0], sizeof root), 0)
        << "a refused refit changes nothing";
}

TEST(BvhBuild, HugeFloorStaysOutOfTheTree) {
    std::vector<glm::dvec3> centres = {
        {1, 0.2, 2}, {-0.95, 0.31, 1.25}, {-0.175, 0.51, 7.5}, {0, -99999.5, 0}};
    std::vector<double> radii = {0.6, 0.6, 0.6, 99999};
    const SphereBvh<float> bvh = buildSphereBvh<float>(centres, radii);
    EXPECT_EQ(bvh.direct, std::vector<std::int32_t>{3});
    EXPECT_EQ(bvh.leafSpheres.size(), 3u);
}

// Double trees keep their boxes in float (BvhNode): a sphere float cannot
// bound stays out of the tree, and the rest are held by boxes rounded outward.
// The huge spheres are found among many, whichever part of the scene they are
// in (the build looks for them in chunks of spheres, on all threads), largest
// first: a ball far larger than the field stays out, and so does one far
// larger than everything smaller than it, but not one only as large as the field.
TEST(BvhBuild, HugeSpheresAnywhereAmongManyStayOutOfTheTree) {
    std::mt19937 random(testSeed(91));
    std::uniform_real_distribution<double> coordinate(-50.0, 50.0);
    std::vector<glm::dvec3> centres;
    std::vector<double> radii;
    for (int i = 0; i < 50000; ++i) {
        centres.push_back({coordinate(random), coordinate(random), coordinate(random)});
        radii.push_back(0.1);
    }
    radii[3] = 1e6;       // far larger than the field: out
    radii[41000] = 1e4;   // far larger than the field without the first: out
    radii[20000] = 60.0;  // about the field's size: in
    for (int threads : {1, 2}) {
        BvhBuildOptions options;
        options.threads = threads;
        const SphereBvh<float> bvh = buildSphereBvh<float>(centres, radii, options);
        EXPECT_EQ(bvh.direct, (std::vector<std::int32_t>{3, 41000})) << threads << " threads";
        EXPECT_EQ(bvh.leafSpheres.size(), 49998u) << threads << " threads";
    }
}

TEST(BvhBuild, DoubleTreeKeepsWhatFloatCannotBoundOutOfTheTree) {
    std::vector<glm::dvec3> centres = {{1, 0.2, 2}, {-0.95, 0.31, 1.25}, {2e38, 0, 5}};
    std::vector<double> radii = {0.6, 0.6, 1.0};
    for (int i = 0; i < 20; ++i) {
        centres.push_back({0.1 * i + 1e-9, 1.0 / 3.0, 2.0 + 1e-12 * i});
        radii.push_back(0.05 + 1e-13 * i);
    }
    const SphereBvh<double> bvh = buildSphereBvh<double>(centres, radii);
    EXPECT_EQ(bvh.direct, std::vector<std::int32_t>{2});
    expectWellFormed(centres, radii, bvh);
}

TEST(BvhBuild, CoincidentSpheresMakeABoundedTree) {
    std::vector<glm::dvec3> centres(1000, glm::dvec3(1, 2, 3));
    std::vector<double> radii(1000, 0.5);
    const SphereBvh<float> bvh = buildSphereBvh<float>(centres, radii);
    expectWellFormed(centres, radii, bvh);
    EXPECT_LE(bvh.depth, 12);
}

TEST(BvhBuild, SeedSceneStaysOnBruteForce) {
    useAcceleration(Acceleration::automatic);
    EXPECT_FALSE(bvhChosen(4));
    EXPECT_TRUE(bvhChosen(kBvhCrossover + 1));
    useAcceleration(Acceleration::bvh);
    EXPECT_TRUE(bvhChosen(1));
    useAcceleration(Acceleration::bruteForce);
    EXPECT_FALSE(bvhChosen(100000));
    useAcceleration(Acceleration::automatic);
}

// Packets of rays of every kind (from the camera, leaving a sphere outwards,
// going into their own sphere, grazing), random subsets of lanes active: the
// tree's nearest hits and transmittances equal brute force's lane for lane.
template <typename T>
void expectSamePackets(const Scene& scene, std::uint32_t seed, const std::string& what) {
    using V = typename Simd<T>::type;
    constexpr int W = RayPacket<T>::kWidth;
    useAcceleration(Acceleration::bvh);
    const PreparedScene<T> s = prepareScene<T>(scene);
    useAcceleration(Acceleration::automatic);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    auto randomDir = [&] {
        Vec<T> d;
        do d = Vec<T>(T(u(rng) * 2 - 1), T(u(rng) * 2 - 1), T(u(rng) * 2 - 1));
        while (glm::dot(d, d) < T(0.01) || glm::dot(d, d) > T(1));
        return glm::normalize(d);
    };
    const int n = s.spheres.count();
    int mismatches = 0;
    for (int trial = 0; trial < 400; ++trial) {
        RayPacket<T> r;
        V distance{};
        for (int l = 0; l < W; ++l) {
            const int k = static_cast<int>(u(rng) * n) % n;
            const Vec<T> c = s.spheres.centre[k];
            const T radius = s.spheres.radius[k];
            const Vec<T> outward = randomDir();
            const Vec<T> p = c + radius * outward;
            const int kind = static_cast<int>(u(rng) * 4);
            Vec<T> d = randomDir();
            if (kind == 0) {  // from near the camera towards a sphere
                r.set(l, Vec<T>(T(0)), glm::normalize(p), -1, false);
            } else if (kind == 1) {  // leaving sphere k outwards
                if (glm::dot(d, outward) < T(0)) d = -d;
                r.set(l, p, d, k, false);
            } else if (kind == 2) {  // going into sphere k
                if (glm::dot(d, outward) > T(0)) d = -d;
                r.set(l, p, d, k, true);
            } else {  // grazing sphere k from outside
                const Vec<T> side = glm::normalize(glm::cross(outward, randomDir()));
                r.set(l, p - T(3) * radius * side, side, -1, false);
            }
            distance[l] = T(u(rng) < 0.5 ? 1e30 : u(rng) * 20 * (1 + radius));
        }
        r.active = static_cast<unsigned>(rng()) & ((1u << W) - 1);
        if (!r.active) r.active = 1;
        // A packet of one ray walks the tree alone (walkOneLane(), leaf_one_ray.h).
        if (trial % 4 == 0) r.active = 1u << (rng() % W);
        V tb, kb, tt, kt;
        packetClosestHits(s.spheres, r, tb, kb);
        bvhClosestHits(s.spheres, *s.bvh, r, tt, kt);
        const V sb = packetTransmittance(s.spheres, s.transparency, r, distance, r.active);
        const V st = bvhTransmittance(s.spheres, s.transparency, *s.bvh, r, distance, r.active);
        for (unsigned bits = r.active; bits; bits &= bits - 1) {
            const int l = __builtin_ctz(bits);
            const bool same = std::memcmp(&tb[l], &tt[l], sizeof(T)) == 0 && kb[l] == kt[l] &&
                              std::memcmp(&sb[l], &st[l], sizeof(T)) == 0;
            if (!same && mismatches++ < 5)
                ADD_FAILURE() << what << ": trial " << trial << " lane " << l << ": brute t "
                              << tb[l] << " k " << kb[l] << " S " << sb[l] << ", tree t " << tt[l]
                              << " k " << kt[l] << " S " << st[l];
        }
    }
    EXPECT_EQ(mismatches, 0) << what;
}

// Rays the sphere test hits, for far, tiny, huge and grazing cases: a sphere
// of radius 1e-4 to 1e6, centred up to 1e7 out, seen from 0.1 to 1e7 radii
// away, the ray aimed near its rim (grazing lines are the hard case). Calls
// hit(o, d, c, radius, t) for each root t > 0 the test reports.
template <typename T, typename Hit>
void forRandomHits(std::uint32_t seed, Hit&& hit) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int trial = 0; trial < 20000; ++trial) {
        const double scale = std::pow(10.0, u(rng) * 10 - 4);
        const double away = std::pow(10.0, u(rng) * 8 - 1);
        const glm::dvec3 c =
            glm::dvec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5) * std::pow(10.0, u(rng) * 7);
        SphereSet<T> set;
        set.add(c, glm::dvec3(0.0), scale, Vec<T>(T(0)));
        const glm::dvec3 toward =
            glm::normalize(glm::dvec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5));
        const glm::dvec3 o = c + toward * (scale * (1 + away));
        const glm::dvec3 side =
            glm::normalize(glm::cross(toward, glm::dvec3(u(rng), u(rng), u(rng))));
        const glm::dvec3 aim = c + side * (scale * (0.9 + 0.2 * u(rng)));
        RayPacket<T> r;
        const Vec<T> ot(o), dt = glm::normalize(Vec<T>(aim - glm::dvec3(ot)));
        r.set(0, ot, dt, -1, false);
        const PacketRoots<T> roots = intersectPacket(set, 0, r, 1u);
        if (!(roots.valid & 1u)) continue;
        for (const T t : {roots.tNear[0], roots.tFar[0]})
            if (t > T(0)) hit(r, ot, dt, c, scale, t);
    }
}

// The exact point o + t d, in long double.
template <typename T>
std::array<long double, 3> exactPoint(const Vec<T>& o, const Vec<T>& d, T t) {
    std::array<long double, 3> p;
    for (int i = 0; i < 3; ++i) p[i] = (long double)o[i] + (long double)t * (long double)d[i];
    return p;
}

// The margin's premise (bvh_traverse.h, kBvhSlack): a root the sphere test
// reports puts the exact point o + t d within a few eps (|o|_1 + |c|_1 + r) of
// the ball. Prints the worst factor.
template <typename T>
double worstExcess(std::uint32_t seed) {
    double worst = 0;
    forRandomHits<T>(seed, [&](const RayPacket<T>&, const Vec<T>& o, const Vec<T>& d,
                               const glm::dvec3& c, double radius, T t) {
        const std::array<long double, 3> p = exactPoint(o, d, t);
        long double d2 = 0;
        for (int i = 0; i < 3; ++i) d2 += (p[i] - (long double)c[i]) * (p[i] - (long double)c[i]);
        const double excess = double(std::sqrt(d2) - (long double)radius);
        const double unit = std::numeric_limits<T>::epsilon() *
                            (std::fabs(o.x) + std::fabs(o.y) + std::fabs(o.z) + std::fabs(c.x) +
                             std::fabs(c.y) + std::fabs(c.z) + radius);
        worst = std::max(worst, excess / unit);
    });
    return worst;
}

TEST(BvhMargin, HitsLieWithinTheMargin) {
    const std::uint32_t seed = testSeed(7);
    const double f = worstExcess<float>(seed), d = worstExcess<double>(seed);
    std::printf("seed %u: worst excess %.3g eps in float, %.3g eps in double (margin %g)\n", seed,
                f, d, double(kBvhSlack<float> / std::numeric_limits<float>::epsilon()));
    EXPECT_LT(f, 8.0);
    EXPECT_LT(d, 8.0);
}

// Double packets' boxes are tested in float (bvh_slabs.h, Walk), the rays
// rounded to float. Each point a double ray's sphere test reports, in the
// tightest box a tree could hold it in (the point itself, rounded outward to
// float), is still met by the ray's box test, by its hit's distance.
TEST(BvhMargin, DoubleRaysWalkedInFloat_MeetTheBoxesOfTheirHits) {
    const std::uint32_t seed = testSeed(8);
    std::printf("seed %u: box tests in %s for double packets\n", seed,
                sizeof(typename Walk<double>::scalar) == sizeof(float) ? "float" : "double");
    int hits = 0, missed = 0;
    forRandomHits<double>(
        seed, [&](const RayPacket<double>& r, const Vec<double>& o, const Vec<double>& d,
                  const glm::dvec3& c, double radius, double t) {
            const std::array<long double, 3> p = exactPoint(o, d, t);
            BvhNode box{};
            for (int i = 0; i < 3; ++i) {
                const float near = float(p[i]);
                box.lo[i] = (long double)near > p[i] ? std::nextafter(near, -INFINITY) : near;
                box.hi[i] = (long double)near < p[i] ? std::nextafter(near, INFINITY) : near;
            }
            // The root of a tree holding the sphere reaches at least this far.
            const double reach = std::fabs(c.x) + std::fabs(c.y) + std::fabs(c.z) + 3 * radius;
            const PacketSlabs<double> slabs = packetSlabs(r, reach);
            typename Simd<double>::type limit{};
            limit[0] = t;
            typename Walk<double>::type entry;
            ++hits;
            if (boxLanes(box, slabs, limit, 1u, entry) != 1u && missed++ < 5)
                ADD_FAILURE() << "o " << o.x << " " << o.y << " " << o.z << ", d " << d.x << " "
                              << d.y << " " << d.z << ", t " << t << ": entry " << entry[0];
        });
    EXPECT_EQ(missed, 0) << "of " << hits;
    EXPECT_GT(hits, 10000);
}

// childrenMet() (one lane, both children at once) against boxLanes() (every
// lane, one child): the same children met and the same entry distances, to
// the bit, with rays along axes, from box faces, with NaN directions and
// limits from 0 to infinity. The lone-lane walk's image rests on it.
template <typename T>
void expectSameChildrenMet(std::uint32_t seed) {
    using V = typename Simd<T>::type;
    constexpr int W = RayPacket<T>::kWidth;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-10.0, 10.0);
    int mismatches = 0, met = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        alignas(64) BvhNode children[2];
        for (BvhNode& n : children) {
            for (int i = 0; i < 3; ++i) {
                const float a = float(u(rng)), b = trial % 7 == 0 ? a : float(u(rng));
                n.lo[i] = std::min(a, b);
                n.hi[i] = std::max(a, b);
            }
            n.first = static_cast<std::int32_t>(rng() % 1000);
            n.count = static_cast<std::int32_t>(rng() % 9) - 1;
        }
        RayPacket<T> r;
        V limit{};
        for (int l = 0; l < W; ++l) {
            Vec<T> o(T(u(rng)), T(u(rng)), T(u(rng))), d(T(u(rng)), T(u(rng)), T(u(rng)));
            const int kind = static_cast<int>(rng() % 5);
            if (kind == 0) {  // towards a point of a child's box
                const BvhNode& n = children[rng() % 2];
                for (int i = 0; i < 3; ++i) d[i] = T(0.5f * (n.lo[i] + n.hi[i])) - o[i];
            }
            if (kind == 1) d[rng() % 3] = T(0);                    // parallel to a face
            if (kind == 2) d = Vec<T>(T(0)), d[rng() % 3] = T(1);  // along an axis
            if (kind == 3) o[rng() % 3] = T(children[rng() % 2].lo[rng() % 3]);  // on a face
            if (kind == 4 && l == 0) d.x = std::numeric_limits<T>::quiet_NaN();
            if (kind != 4 && glm::dot(d, d) > T(0)) d = glm::normalize(d);
            r.set(l, o, d, -1, false);
            const int reach = static_cast<int>(rng() % 4);
            limit[l] = reach == 0   ? T(0)
                       : reach == 1 ? std::numeric_limits<T>::infinity()
                                    : T(std::fabs(u(rng)) * 3);
        }
        const PacketSlabs<T> slabs = packetSlabs(r, T(30));
        typename Walk<T>::type entries[2];
        const unsigned lanes = (1u << W) - 1;
        const unsigned inChild[2] = {boxLanes(children[0], slabs, limit, lanes, entries[0]),
                                     boxLanes(children[1], slabs, limit, lanes, entries[1])};
        for (int l = 0; l < W; ++l) {
            typename Walk<T>::scalar entry[2];
            const unsigned alone = childrenMet(children, laneSlabs(slabs, l), limit[l], entry);
            for (int c = 0; c < 2; ++c) {
                const bool inPacket = (inChild[c] >> l) & 1u, byItself = (alone >> c) & 1u;
                met += inPacket;
                const bool same =
                    inPacket == byItself &&
                    (!inPacket || std::memcmp(&entry[c], &entries[c][l], sizeof entry[c]) == 0);
                if (!same && mismatches++ < 5)
                    ADD_FAILURE() << "trial " << trial << " lane " << l << " child " << c
                                  << ": packet " << inPacket << " entry " << entries[c][l]
                                  << ", alone " << byItself << " entry " << entry[c];
            }
        }
    }
    EXPECT_EQ(mismatches, 0);
    EXPECT_GT(met, 2 * 2000 * W / 10);  // a fair share of the tests meet a box
}

TEST(BvhSlabs, BothChildrenAtOnce_SameAsEachBoxInThePacket) {
    const std::uint32_t seed = testSeed(31);
    std::printf("seed %u\n", seed);
    expectSameChildrenMet<float>(seed);
    expectSameChildrenMet<double>(seed);
}

TEST(BvhPackets, SameHitsAndTransmittanceAsBruteForce) {
    const std::uint32_t seed = testSeed(99);
    std::printf("seed %u\n", seed);
    int variant = 0;
    for (int count : {2, 7, 50, 500, 3000}) {
        for (Layout layout :
             {Layout::Field, Layout::Overlapping, Layout::Nested, Layout::Far, Layout::Tiny}) {
            const std::uint32_t sceneSeed = seed * 17 + variant++;
            const Scene scene = randomScene(count, layout, sceneSeed, true);
            const std::string what = std::to_string(count) + " " + layoutName(layout) +
                                     ", scene seed " + std::to_string(sceneSeed);
            expectSamePackets<float>(scene, sceneSeed, what + ", float");
            expectSamePackets<double>(scene, sceneSeed, what + ", double");
        }
    }
}

// With the camera among 10,000 balls the shadow rays scatter, and one of the
// two render threads makes the light's buffer (light_buffer.h) while the
// other goes on without it; the picture is the one rendered without buffers,
// bit for bit. On the field, whose shadow packets keep together, neither
// thread makes one.
TEST(RendererLightBuffer, MadeMidRenderWhereShadowRaysScatter_ChangesNoPixel) {
    for (const char* layout : {"inside", "field"}) {
        SCOPED_TRACE(layout);
        const Scene scene = sphereField(*fieldLayout(layout, 10000), 320, 240);
        RenderOptions with = oneShotOptions();
        with.threads = 2;
        RenderOptions without = with;
        without.lightBuffers = false;
        const RenderResult a = render(scene, with);
        const RenderResult b = render(scene, without);
        EXPECT_EQ(a.lightBuffers, std::string(layout) == "inside" ? 1 : 0);
        EXPECT_EQ(b.lightBuffers, 0);
        EXPECT_EQ(a.rays.total(), b.rays.total());
        EXPECT_TRUE(test::samePixels(a.image, b.image)) << test::firstDifference(a.image, b.image);
    }
}

}  // namespace
}  // namespace whitted
