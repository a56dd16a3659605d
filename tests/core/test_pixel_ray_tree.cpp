// A pixel's ray tree against the render it explains: its value is that pixel
// of a one-sample render, bit for bit, on every shipped scene and on random
// fields of matte, mirror and glass balls, in both precisions, at the
// picture's edges and corners and where light is totally reflected inside
// glass; and what its rays add up to is that value but for rounding.
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/pixel_ray_tree.h"
#include "scene/scene_io.h"
#include "sphere_field.h"
#include "support/core_support.h"
#include "support/test_support.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;

// The scene at width x height, one sample a pixel, in `precision`.
Scene oneSample(Scene scene, int width, int height, Precision precision) {
    scene.render.width = width;
    scene.render.height = height;
    scene.render.samplesPerPixel = 1;
    scene.render.precision = precision;
    return scene;
}

// The corners, the middle of each edge, and every `step`th pixel between.
std::vector<std::pair<int, int>> pixelsOf(const Scene& scene, int step) {
    const int w = scene.render.width, h = scene.render.height;
    std::vector<std::pair<int, int>> pixels{{0, 0},     {w - 1, 0},     {0, h - 1}, {w - 1, h - 1},
                                            {w / 2, 0}, {w / 2, h - 1}, {0, h / 2}, {w - 1, h / 2}};
    for (int y = step / 2; y < h; y += step)
        for (int x = step / 3; x < w; x += step) pixels.emplace_back(x, y);
    return pixels;
}

struct Seen {
    int rays = 0, tir = 0, cutOff = 0, shadows = 0;
};

void count(const RayTreeNode& n, Seen& seen) {
    ++seen.rays;
    seen.tir += n.totalInternalReflection;
    seen.cutOff += n.cutOff;
    seen.shadows += n.kind == RayTreeNode::Kind::Shadow;
    for (const RayTreeNode& c : n.children) count(c, seen);
}

// Every pixel's tree: its value the rendered pixel's, bit for bit, its rays'
// contributions that value within rounding.
Seen expectTreesMatchTheRender(const Scene& scene, int step, const std::string& what) {
    const Image image = test::renderImage(scene);
    const double tolerance = scene.render.precision == Precision::Float ? 1e-5 : 1e-12;
    Seen seen;
    int mismatches = 0;
    for (const auto& [x, y] : pixelsOf(scene, step)) {
        const PixelRayTree tree = pixelRayTree(scene, x, y);
        count(tree.root, seen);
        const float* rendered = image.pixel(x, y);
        for (int c = 0; c < 3; ++c) {
            if (float(tree.value[c]) != rendered[c] && mismatches++ < 5)
                ADD_FAILURE() << what << ": pixel " << x << "," << y << " channel " << c
                              << ": tree " << tree.value[c] << ", render " << rendered[c];
            const double sum = sumOfContributions(tree.root)[c];
            EXPECT_NEAR(sum, tree.root.radiance[c], tolerance * (1.0 + tree.root.radiance[c]))
                << what << ": pixel " << x << "," << y;
        }
    }
    EXPECT_EQ(mismatches, 0) << what;
    return seen;
}

TEST(PixelRayTree, EveryShippedScene_ValueIsTheRenderedPixelInBothPrecisions) {
    int scenes = 0;
    for (const auto& entry : fs::recursive_directory_iterator(WHITTED_SCENES_DIR)) {
        if (entry.path().extension() != ".json") continue;
        const Scene file = loadScene(entry.path().string());
        for (Precision p : {Precision::Float, Precision::Double})
            expectTreesMatchTheRender(
                oneSample(file, 40, 30, p), 5,
                entry.path().filename().string() + " " + std::string(precisionName(p)));
        ++scenes;
    }
    EXPECT_GE(scenes, 19);  // scenes/ and scenes/extremes/
}

TEST(PixelRayTree, RandomGlassAndMirrorFields_ValueIsTheRenderedPixel) {
    Seen seen;
    for (std::uint32_t seed : {3u, 11u, 29u}) {
        FieldOptions field;
        field.count = 150;
        field.seed = seed;
        field.halfWidth = 4.0;
        field.depth = 8.0;
        for (Precision p : {Precision::Float, Precision::Double}) {
            Scene scene = oneSample(sphereField(field), 48, 36, p);
            scene.render.maxDepth = 3;  // deep trees end in cut-off rays
            const Seen s = expectTreesMatchTheRender(scene, 3, "field " + std::to_string(seed));
            seen.rays += s.rays;
            seen.cutOff += s.cutOff;
            seen.shadows += s.shadows;
        }
    }
    EXPECT_GT(seen.cutOff, 0) << "no ray was cut off by the depth: the test tests less";
    EXPECT_GT(seen.shadows, 0);
}

// The extremes' glass block where light is trapped: total internal reflection
// sends the transparency's share along the reflected ray.
TEST(PixelRayTree, TotalInternalReflection_FoundAndTheValueStillTheRenderedPixel) {
    const Scene tir = loadScene(WHITTED_SCENES_DIR "/extremes/tir-glass.json");
    int seen = 0;
    for (Precision p : {Precision::Float, Precision::Double})
        seen += expectTreesMatchTheRender(oneSample(tir, 64, 48, p), 2, "tir-glass").tir;
    EXPECT_GT(seen, 0) << "no ray was totally reflected: the test tests less";
}

// What a user reads in the tree of a pixel of the seed: the camera ray hits
// a ball, a shadow ray goes towards each light, and the numbers add up.
TEST(PixelRayTree, SeedCentre_CameraRayHitsABallWithAShadowRayPerLight) {
    const Scene seed = oneSample(loadScene(test::kSeedScenePath), 64, 48, Precision::Double);
    const PixelRayTree tree = pixelRayTree(seed, 32, 24);
    const RayTreeNode& root = tree.root;
    EXPECT_EQ(root.kind, RayTreeNode::Kind::Camera);
    EXPECT_EQ(root.weight, 1.0);
    ASSERT_GE(root.hit, 0);
    EXPECT_TRUE(root.entering);
    EXPECT_GT(root.t, 0.0);
    int shadows = 0;
    for (const RayTreeNode& c : root.children) {
        if (c.kind != RayTreeNode::Kind::Shadow) continue;
        ++shadows;
        EXPECT_GE(c.transmittance, 0.0);
        EXPECT_LE(c.transmittance, 1.0);
        EXPECT_EQ(c.contribution, Vec3(0.0));
    }
    EXPECT_EQ(shadows, int(seed.lights.size()));
    // The origin is the camera's, the direction a unit vector.
    EXPECT_EQ(root.origin, seed.camera.position);
    EXPECT_NEAR(glm::length(root.direction), 1.0, 1e-12);
}

TEST(PixelRayTree, PixelOutsideThePicture_RefusedNamingIt) {
    const Scene seed = oneSample(loadScene(test::kSeedScenePath), 64, 48, Precision::Float);
    try {
        pixelRayTree(seed, 64, 0);
        FAIL() << "no exception";
    } catch (const std::out_of_range& e) {
        EXPECT_EQ(std::string(e.what()), "pixel 64,0 is outside the 64x48 picture");
    }
    EXPECT_THROW(pixelRayTree(seed, 0, -1), std::out_of_range);
}

}  // namespace
}  // namespace whitted
