// End-to-end tests of whitted-field: its fields load as scenes, the
// same flags give the same file, scenes/field.json is its output, and a field
// renders the same through the sphere BVH as by brute force.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "image/image_io.h"
#include "scene/scene_io.h"
#include "support/test_support.h"

namespace fs = std::filesystem;
using namespace whitted;
using whitted::test::TempDir;

namespace {

// whitted-field with the flags and "-o out", its stdout and stderr together.
test::ProgramRun field(const std::vector<std::string>& flags, const fs::path& out) {
    return test::runProgram(WHITTED_FIELD_EXE, test::appended(flags, {"-o", out.string()}),
                            test::Stderr::Merged);
}

// A float TIFF, so that equal files mean equal pixels; `env` ("NAME=value")
// before the command.
test::ProgramRun renderTiff(const std::string& env, const fs::path& scene, const fs::path& out) {
    return test::runProgram(
        WHITTED_RENDER_EXE,
        {scene.string(), "--quiet", "--width", "96", "--height", "64", "-o", out.string()},
        test::Stderr::Merged, env);
}

}  // namespace

TEST(WhittedField, Output_LoadsWithCountBallsOfFiveMaterialsAndAFloor) {
    TempDir dir;
    const test::ProgramRun r = field({"50", "--seed", "7"}, dir / "f.json");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const Scene scene = loadScene(dir / "f.json");
    ASSERT_EQ(scene.spheres.size(), 51u);
    std::set<std::string> used;
    for (const Sphere& s : scene.spheres) used.insert(s.material);
    EXPECT_EQ(used, (std::set<std::string>{"blue", "purple", "white", "mirror", "glass", "floor"}));
    EXPECT_EQ(scene.spheres.back().radius, 99999);
    for (std::size_t i = 0; i + 1 < scene.spheres.size(); ++i) {
        const Sphere& s = scene.spheres[i];
        EXPECT_DOUBLE_EQ(s.center.y - s.radius, -0.5) << s.name << " rests on the floor";
    }
}

TEST(WhittedField, SameFlags_SameBytes_OtherSeed_OtherBalls) {
    TempDir dir;
    ASSERT_EQ(field({"30", "--seed", "3"}, dir / "a.json").exitCode, 0);
    ASSERT_EQ(field({"30", "--seed", "3"}, dir / "b.json").exitCode, 0);
    ASSERT_EQ(field({"30", "--seed", "4"}, dir / "c.json").exitCode, 0);
    EXPECT_EQ(test::readFile(dir / "a.json"), test::readFile(dir / "b.json"));
    EXPECT_NE(loadScene(dir / "a.json").spheres[0], loadScene(dir / "c.json").spheres[0]);
}

TEST(WhittedField, BadFlags_ExitTwoAndWriteNothing) {
    TempDir dir;
    EXPECT_EQ(field({"-3"}, dir / "f.json").exitCode, 2);
    EXPECT_EQ(field({"10", "--half-width", "0"}, dir / "f.json").exitCode, 2);
    EXPECT_FALSE(fs::exists(dir / "f.json"));
}

// The README's command for the shipped example remakes it byte for byte.
TEST(WhittedField, ShippedFieldScene_IsTheGeneratorsOutput) {
    TempDir dir;
    const test::ProgramRun r =
        field({"2500", "--half-width", "12", "--length", "40", "--near", "0"}, dir / "field.json");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_TRUE(test::readFile(dir / "field.json") ==
                test::readFile(WHITTED_SCENES_DIR "/field.json"))
        << "scenes/field.json is not what whitted-field makes with these flags";
}

TEST(WhittedField, ShippedFieldScene_RendersWithWhittedRender) {
    TempDir dir;
    const test::ProgramRun r = renderTiff("", WHITTED_SCENES_DIR "/field.json", dir / "field.tif");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const Image image = readImage(dir / "field.tif");
    EXPECT_EQ(image.width, 96);
    EXPECT_EQ(image.height, 64);
}

// 50 balls is above the automatic crossover; both ways must give the same pixels.
TEST(WhittedField, GeneratedField_BvhRenderEqualsBruteForceBitForBit) {
    TempDir dir;
    ASSERT_EQ(
        field({"50", "--half-width", "2", "--length", "6", "--near", "0"}, dir / "f.json").exitCode,
        0);
    ASSERT_EQ(renderTiff("WHITTED_ACCEL=bvh", dir / "f.json", dir / "bvh.tif").exitCode, 0);
    ASSERT_EQ(renderTiff("WHITTED_ACCEL=brute", dir / "f.json", dir / "brute.tif").exitCode, 0);
    const Image bvh = readImage(dir / "bvh.tif"), brute = readImage(dir / "brute.tif");
    EXPECT_TRUE(bvh == brute) << "the BVH render differs from brute force";
    // Not an empty picture that would be equal either way: balls and floor both show.
    float lo = 1, hi = 0;
    for (float v : bvh.rgb) lo = std::min(lo, v), hi = std::max(hi, v);
    EXPECT_LT(lo, 0.05f);
    EXPECT_GT(hi, 0.5f);
}

namespace {

// whitted-field's scene for the flags, read back; fails the test on an error.
Scene fieldScene(const TempDir& dir, const std::vector<std::string>& flags) {
    const test::ProgramRun r = field(flags, dir / "layout.json");
    EXPECT_EQ(r.exitCode, 0) << r.out;
    return loadScene(dir / "layout.json");
}

// The balls, without the floor (the last sphere).
std::vector<Sphere> ballsOf(const Scene& scene) {
    return {scene.spheres.begin(), scene.spheres.end() - 1};
}

// How many 2 x 2 squares of the floor hold a ball's centre.
std::size_t occupiedSquares(const Scene& scene) {
    std::set<std::pair<long, long>> squares;
    for (const Sphere& s : ballsOf(scene))
        squares.insert({std::lround(std::floor(s.center.x / 2)),
                        std::lround(std::floor(s.center.z / 2))});
    return squares.size();
}

std::size_t countOf(const Scene& scene, const std::string& material) {
    const std::vector<Sphere> balls = ballsOf(scene);
    return std::size_t(std::count_if(balls.begin(), balls.end(),
                                     [&](const Sphere& s) { return s.material == material; }));
}

}  // namespace

// In the same 100 x 98.5 box (2,463 squares of 2 x 2), 2,000 balls spread
// over most squares; in 64 clumps they keep to a few hundred.
TEST(WhittedField, LayoutClustered_GathersTheBallsInClumps) {
    TempDir dir;
    const std::size_t spread = occupiedSquares(fieldScene(dir, {"2000"}));
    const std::size_t clumped = occupiedSquares(fieldScene(dir, {"2000", "--layout", "clustered"}));
    EXPECT_GT(spread, 1200u);
    EXPECT_LT(clumped, 800u);
}

TEST(WhittedField, LayoutRadii_SpreadsThreeDecadesAndKeepsClearOfTheCamera) {
    TempDir dir;
    const Scene scene = fieldScene(dir, {"2000", "--layout", "radii"});
    double smallest = 1e9, largest = 0;
    for (const Sphere& s : ballsOf(scene)) {
        smallest = std::min(smallest, s.radius);
        largest = std::max(largest, s.radius);
        EXPECT_GT(glm::distance(s.center, scene.camera.position), s.radius + 1) << s.name;
    }
    EXPECT_LT(smallest, 0.012);
    EXPECT_GT(largest, 8.0);
}

TEST(WhittedField, LayoutsGlassAndMirrors_FourBallsInFive) {
    TempDir dir;
    EXPECT_EQ(countOf(fieldScene(dir, {"1000", "--layout", "glass"}), "glass"), 800u);
    EXPECT_EQ(countOf(fieldScene(dir, {"1000", "--layout", "mirrors"}), "mirror"), 800u);
    EXPECT_EQ(countOf(fieldScene(dir, {"1000"}), "glass"), 200u);
}

TEST(WhittedField, LayoutInside_PutsTheCameraAmongFloatingBalls) {
    TempDir dir;
    const Scene scene = fieldScene(dir, {"1000", "--layout", "inside"});
    const Vec3 eye = scene.camera.position;
    int behind = 0, left = 0, above = 0, floating = 0;
    for (const Sphere& s : ballsOf(scene)) {
        behind += s.center.z < eye.z;
        left += s.center.x < eye.x;
        above += s.center.y > eye.y;
        floating += s.center.y - s.radius > -0.5 + 1;
    }
    EXPECT_GT(behind, 400);
    EXPECT_GT(left, 400);
    EXPECT_GT(above, 300);
    EXPECT_GT(floating, 500);
}

TEST(WhittedField, LayoutAbove_LooksStraightDownOnEveryBall) {
    TempDir dir;
    const Scene scene = fieldScene(dir, {"1000", "--layout", "above"});
    const Vec3 view = glm::normalize(scene.camera.lookAt - scene.camera.position);
    EXPECT_NEAR(view.y, -1.0, 1e-12);
    for (const Sphere& s : ballsOf(scene)) EXPECT_LT(s.center.y + s.radius, scene.camera.position.y);
}

// Four balls a square unit at every count: 400 balls within |x| <= 5, 1,600
// within |x| <= 10, reaching past 5.
TEST(WhittedField, LayoutUniform_TheBoxGrowsWithTheCount) {
    TempDir dir;
    double widest = 0;
    for (const Sphere& s : ballsOf(fieldScene(dir, {"400", "--layout", "uniform"})))
        widest = std::max(widest, std::abs(s.center.x));
    EXPECT_LE(widest, 5.0);
    EXPECT_GT(widest, 4.0);
    widest = 0;
    for (const Sphere& s : ballsOf(fieldScene(dir, {"1600", "--layout", "uniform"})))
        widest = std::max(widest, std::abs(s.center.x));
    EXPECT_LE(widest, 10.0);
    EXPECT_GT(widest, 9.0);
}

TEST(WhittedField, LayoutWithBoxFlags_TheFlagsWin) {
    TempDir dir;
    for (const Sphere& s : ballsOf(fieldScene(dir, {"300", "--layout", "glass", "--half-width",
                                                    "3", "--near", "4", "--length", "2"}))) {
        EXPECT_LE(std::abs(s.center.x), 3.0);
        EXPECT_GE(s.center.z, 4.0);
        EXPECT_LE(s.center.z, 6.0);
    }
}

TEST(WhittedField, UnknownLayout_ExitTwoNamingTheFlagAndWriteNothing) {
    TempDir dir;
    const test::ProgramRun r = field({"10", "--layout", "spiral"}, dir / "f.json");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.out.find("--layout"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("spiral"), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(dir / "f.json"));
}
