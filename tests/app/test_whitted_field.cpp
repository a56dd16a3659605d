// End-to-end tests of whitted-field (issue 12): its fields load as scenes, the
// same flags give the same file, scenes/field.json is its output, and a field
// renders the same through the sphere BVH as by brute force.
#include <algorithm>
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
