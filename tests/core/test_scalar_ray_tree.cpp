// The scalar ray tree (core/tracer/scalar_ray_tree.h) is a second statement of
// the packet tracer's recursion, kept as an oracle of it: walked for every
// pixel, it must trace exactly the rays the tracer counts, camera, reflected
// and refracted, on scenes nobody tuned it on: random fields of matte, mirror
// and glass balls (brute force and BVH), the shipped scenes, every depth,
// both precisions. A rule changed in one and not the other (an order, a
// threshold, total internal reflection, self-intersection) changes what the
// later rays hit, and the counts part.
#include <filesystem>
#include <string>
#include <type_traits>

#include <gtest/gtest.h>

#include "scene/scene_io.h"
#include "sphere_field.h"
#include "tracer/renderer.h"
#include "tracer/scalar_ray_tree.h"

namespace whitted {
namespace {

// Counts the rays the walk traces; descends into every secondary ray, as the
// tracer does (its weights only scale radiance).
template <typename T>
struct RayCounter {
    static constexpr bool kWantsShadows = false;
    std::uint64_t traced = 0, refracted = 0;
    void hit(int) { ++traced; }
    void shadow(int) {}
    void tir(bool total) { refracted += !total; }
    void cutOff(T) {}
    bool descend(T, int) { return true; }
};

// The walk's counts over every pixel, as the tracer's RayCounts.
template <typename T>
RayCounts walkEveryPixel(const Scene& scene) {
    const PreparedScene<T> prepared = prepareScene<T>(scene);
    RayCounter<T> counter;
    for (int y = 0; y < scene.render.height; ++y)
        for (int x = 0; x < scene.render.width; ++x)
            ScalarRayTree<T, RayCounter<T>>(prepared, counter).tracePixel(x, y);
    RayCounts counts;
    counts.camera = std::uint64_t(scene.render.width) * scene.render.height;
    counts.refraction = counter.refracted;
    counts.reflection = counter.traced - counts.camera - counter.refracted;
    return counts;
}

void expectSameRays(Scene scene, const std::string& what) {
    scene.render.width = 96;
    scene.render.height = 72;
    scene.render.samplesPerPixel = 1;  // the walk follows the pixel centre's ray
    RenderOptions oneShot;
    oneShot.progressive = false;
    for (const Precision precision : {Precision::Float, Precision::Double})
        for (const int depth : {0, 1, 3, 5, 8}) {
            scene.render.precision = precision;
            scene.render.maxDepth = depth;
            const RayCounts traced = render(scene, oneShot).rays;
            const RayCounts walked = precision == Precision::Float ? walkEveryPixel<float>(scene)
                                                                   : walkEveryPixel<double>(scene);
            const std::string where = what + ", " + std::string(precisionName(precision)) +
                                      ", depth " + std::to_string(depth);
            EXPECT_EQ(walked.camera, traced.camera) << where;
            EXPECT_EQ(walked.reflection, traced.reflection) << where;
            EXPECT_EQ(walked.refraction, traced.refraction) << where;
        }
}

TEST(ScalarRayTree, TracesTheTracersRays_OnRandomFieldsOfMirrorAndGlassBalls) {
    // 12 balls: every ray tests every sphere; 400: through the BVH.
    for (const int count : {12, 400})
        for (const std::uint32_t seed : {1u, 2u, 3u}) {
            // halfWidth 3: close enough that balls fill the picture
            const Scene scene =
                sphereField({.count = count, .seed = seed, .halfWidth = 3.0, .depth = 8.0});
            expectSameRays(scene, std::to_string(count) + " balls, seed " + std::to_string(seed));
        }
}

TEST(ScalarRayTree, TracesTheTracersRays_OnTheShippedScenes) {
    for (const char* name : {"seed", "mirrors", "glass", "whitted-1980"})
        expectSameRays(loadScene(std::filesystem::path(WHITTED_SCENES_DIR) / name += ".json"), name);
}

// The counts can tell: at depth 5 a field sends reflected and refracted rays.
TEST(ScalarRayTree, TheFieldsSendReflectedAndRefractedRays) {
    const Scene scene = sphereField({.count = 400, .halfWidth = 3.0, .depth = 8.0}, 96, 72);
    const RayCounts walked = walkEveryPixel<float>(scene);
    EXPECT_GT(walked.reflection, 1000u);
    EXPECT_GT(walked.refraction, 300u);
}

}  // namespace
}  // namespace whitted
