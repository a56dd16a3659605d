// End-to-end tests of the whitted-render program (SPEC §7): exit codes, the image
// and stats it writes, messages on stderr, and nothing left behind on failure.
#include <sched.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "image/image_error.h"
#include "image/image_io.h"
#include "support/core_support.h"
#include "support/test_support.h"
#include "tracer/renderer.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;
using test::ProgramRun;
using test::TempDir;

// whitted-render with the arguments, its stdout and stderr captured apart.
const test::Program runRender{WHITTED_RENDER_EXE};

std::string describe(const ProgramRun& r) {
    return "exit " + std::to_string(r.exitCode) + "\n--- stderr ---\n" + r.err;
}

TEST(WhittedRender, SmallRender_ExitsZeroAndWritesImageOfRequestedSize) {
    TempDir dir;
    const fs::path out = dir / "seed.png";
    const ProgramRun r = runRender({test::kSeedScenePath, "-o", out.string(), "--width", "64",
                                    "--height", "48", "--threads", "2"});
    ASSERT_EQ(r.exitCode, 0) << describe(r);
    const Image img = readImage(out);
    EXPECT_EQ(img.width, 64);
    EXPECT_EQ(img.height, 48);
    // The seed's floor and balls: not a blank image.
    float lo = 1, hi = 0;
    for (float v : img.rgb) lo = std::min(lo, v), hi = std::max(hi, v);
    EXPECT_LT(lo, 0.05f);
    EXPECT_GT(hi, 0.5f);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"seed.png"}) << test::joined(dir.entries());
}

TEST(WhittedRender, EveryFormat_WritesReadableImage) {
    TempDir dir;
    for (const char* name : {"o.png", "o.jpg", "o.tif", "o.exr", "o.hdr"}) {
        const fs::path out = dir / name;
        const ProgramRun r = runRender({test::kSeedScenePath, "-o", out.string(), "--width", "31",
                                        "--height", "17", "--quiet"});
        ASSERT_EQ(r.exitCode, 0) << name << "\n" << describe(r);
        const Image img = readImage(out);
        EXPECT_EQ(img.width, 31) << name;
        EXPECT_EQ(img.height, 17) << name;
    }
}

TEST(WhittedRender, Stats_HaveEverySpecKeyAndConsistentRayCounts) {
    TempDir dir;
    const fs::path out = dir / "o.exr", stats = dir / "stats.json";
    const ProgramRun r =
        runRender({test::kSeedScenePath, "-o", out.string(), "--width", "40", "--height", "30",
                   "--spp", "3", "--depth", "4", "--threads", "2", "--stats", stats.string()});
    ASSERT_EQ(r.exitCode, 0) << describe(r);
    const nlohmann::json j = nlohmann::json::parse(test::readFile(stats));
    for (const char* key : {"width", "height", "samples_per_pixel", "max_depth", "precision",
                            "threads", "seconds", "rays", "mrays_per_second"})
        EXPECT_TRUE(j.contains(key)) << "missing " << key << " in\n" << j.dump(2);
    for (const char* key : {"camera", "shadow", "reflection", "refraction", "total"})
        EXPECT_TRUE(j["rays"].contains(key)) << "missing rays." << key << " in\n" << j.dump(2);
    EXPECT_EQ(j["width"], 40);
    EXPECT_EQ(j["height"], 30);
    EXPECT_EQ(j["samples_per_pixel"], 3);
    EXPECT_EQ(j["max_depth"], 4);
    EXPECT_EQ(j["precision"], "float");  // the seed's own
    EXPECT_EQ(j["threads"], 2);
    EXPECT_GE(j["seconds"].get<double>(), 0.0);
    EXPECT_GE(j["mrays_per_second"].get<double>(), 0.0);
    // The two threads' time on the CPU: some, and no more than they had.
    const double cpu = j["cpu_seconds"].get<double>();
    EXPECT_GT(cpu, 0.0);
    EXPECT_LE(cpu, 2 * j["seconds"].get<double>() + 1e-3);
    EXPECT_EQ(j["light_buffers"], 0);  // the seed's four balls have no tree to spare
    const auto& rays = j["rays"];
    const auto camera = rays["camera"].get<std::uint64_t>();
    EXPECT_EQ(camera, 40u * 30u * 3u);
    EXPECT_EQ(rays["total"].get<std::uint64_t>(), camera + rays["shadow"].get<std::uint64_t>() +
                                                      rays["reflection"].get<std::uint64_t>() +
                                                      rays["refraction"].get<std::uint64_t>());
    EXPECT_GT(rays["shadow"].get<std::uint64_t>(), 0u);
    EXPECT_GT(rays["reflection"].get<std::uint64_t>(), 0u);
}

// Confined to one core, as a Slurm task or `taskset` confines it, "all
// cores" is that one core: the render runs one thread, where unconfined it
// runs several (one for each core of the machine, up to one a tile).
TEST(WhittedRender, ConfinedToOneCore_RendersOnOneThreadByDefault) {
    TempDir dir;
    const fs::path out = dir / "o.exr", stats = dir / "stats.json";
    const std::vector<std::string> args = {
        test::kSeedScenePath, "-o", out.string(), "--width",     "64",
        "--height",           "64", "--stats",    stats.string()};
    const auto threadsUsed = [&](const ProgramRun& r) {
        EXPECT_EQ(r.exitCode, 0) << describe(r);
        return nlohmann::json::parse(test::readFile(stats))["threads"].get<int>();
    };
    // The first core this test may run on (not always core 0 in a container).
    cpu_set_t allowed;
    ASSERT_EQ(sched_getaffinity(0, sizeof allowed, &allowed), 0);
    int first = 0;
    while (!CPU_ISSET(first, &allowed)) ++first;
    std::vector<std::string> confined = {"-c", std::to_string(first), WHITTED_RENDER_EXE};
    confined.insert(confined.end(), args.begin(), args.end());
    EXPECT_EQ(threadsUsed(test::runProgram("taskset", confined)), 1);
    if (CPU_COUNT(&allowed) > 1) {
        EXPECT_GT(threadsUsed(runRender(args)), 1);
    }
}

TEST(WhittedRender, Flags_OverrideSceneSettings) {
    TempDir dir;
    const fs::path out = dir / "o.tif", stats = dir / "stats.json";
    const ProgramRun r =
        runRender({test::kSeedScenePath, "-o", out.string(), "--width", "20", "--height", "10",
                   "--precision", "double", "--depth", "0", "--stats", stats.string(), "--quiet"});
    ASSERT_EQ(r.exitCode, 0) << describe(r);
    const nlohmann::json j = nlohmann::json::parse(test::readFile(stats));
    EXPECT_EQ(j["precision"], "double");
    EXPECT_EQ(j["max_depth"], 0);
    EXPECT_EQ(j["samples_per_pixel"], 1);  // the seed's own
    EXPECT_EQ(j["rays"]["reflection"], 0) << "depth 0 must trace no reflections";
    EXPECT_EQ(j["rays"]["camera"], 200);
}

TEST(WhittedRender, Quiet_PrintsNothingOnSuccess) {
    TempDir dir;
    const ProgramRun r = runRender({test::kSeedScenePath, "-o", (dir / "q.png").string(), "--width",
                                    "16", "--height", "12", "--quiet"});
    ASSERT_EQ(r.exitCode, 0) << describe(r);
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(r.out, "");
}

TEST(WhittedRender, WithoutQuiet_ReportsWhatItWrote) {
    TempDir dir;
    const fs::path out = dir / "v.png";
    const ProgramRun r =
        runRender({test::kSeedScenePath, "-o", out.string(), "--width", "16", "--height", "12"});
    ASSERT_EQ(r.exitCode, 0) << describe(r);
    EXPECT_NE(r.err.find(out.string()), std::string::npos) << r.err;
}

// ---- bad input: exit 2, message on stderr, no output -----------------------------

TEST(WhittedRender, BadSceneFile_ExitsTwoNamingFileAndJsonPath) {
    TempDir dir;
    nlohmann::json j = nlohmann::json::parse(test::readFile(test::kSeedScenePath));
    j["spheres"][2]["radius"] = -0.6;
    const fs::path scene = dir / "bad.json", out = dir / "o.png";
    test::writeFile(scene, j.dump(2));
    const ProgramRun r = runRender({scene.string(), "-o", out.string()});
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_NE(r.err.find(scene.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("spheres[2].radius"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"bad.json"}) << test::joined(dir.entries());
}

TEST(WhittedRender, SceneWithInfiniteNumber_ExitsTwoNamingJsonPath) {
    TempDir dir;
    std::string text = test::readFile(test::kSeedScenePath);
    const std::string from = "\"radius\": 0.6";
    ASSERT_NE(text.find(from), std::string::npos);
    text.replace(text.find(from), from.size(), "\"radius\": 1e999");  // spheres[0]
    const fs::path scene = dir / "inf.json", out = dir / "o.png";
    test::writeFile(scene, text);
    const ProgramRun r = runRender({scene.string(), "-o", out.string()});
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_NE(r.err.find(scene.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("spheres[0].radius"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
}

TEST(WhittedRender, InvalidJson_ExitsTwoNamingFile) {
    TempDir dir;
    const fs::path scene = dir / "broken.json", out = dir / "o.png";
    test::writeFile(scene, "{\"format\": \"whitted-scene\", \"version\": 1,");
    const ProgramRun r = runRender({scene.string(), "-o", out.string()});
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_NE(r.err.find(scene.string()), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
}

TEST(WhittedRender, MissingSceneFile_ExitsTwo) {
    TempDir dir;
    const fs::path scene = dir / "nothing here.json", out = dir / "o.png";
    const ProgramRun r = runRender({scene.string(), "-o", out.string()});
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_NE(r.err.find("nothing here.json"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
}

TEST(WhittedRender, BadFlags_ExitTwoWithMessageAndNoOutput) {
    TempDir dir;
    const fs::path out = dir / "o.png";
    const std::vector<std::vector<std::string>> cases = {
        {"--spp", "0"},        {"--spp", "65537"}, {"--precision", "half"}, {"--width", "0"},
        {"--height", "16385"}, {"--depth", "65"},  {"--depth", "-1"},       {"--threads", "-2"},
        {"--width", "many"},   {"--frobnicate"},
    };
    for (const auto& flags : cases) {
        std::vector<std::string> args = {test::kSeedScenePath, "-o", out.string()};
        args.insert(args.end(), flags.begin(), flags.end());
        const ProgramRun r = runRender(args);
        std::string label;
        for (const auto& f : flags) label += f + " ";
        EXPECT_EQ(r.exitCode, 2) << label << describe(r);
        EXPECT_FALSE(r.err.empty()) << label;
        EXPECT_FALSE(fs::exists(out)) << label;
    }
    // No output flag at all, and no scene at all.
    EXPECT_EQ(runRender({test::kSeedScenePath}).exitCode, 2);
    EXPECT_EQ(runRender({"-o", out.string()}).exitCode, 2);
    EXPECT_TRUE(dir.entries().empty()) << test::joined(dir.entries());
}

TEST(WhittedRender, UnknownOutputExtension_ExitsTwoAndWritesNothing) {
    TempDir dir;
    for (const char* name : {"o.bmp", "o", "o.gif"}) {
        const fs::path out = dir / name;
        const ProgramRun r =
            runRender({test::kSeedScenePath, "-o", out.string(), "--width", "8", "--height", "8"});
        EXPECT_EQ(r.exitCode, 2) << name << "\n" << describe(r);
        EXPECT_NE(r.err.find(name), std::string::npos) << r.err;
    }
    EXPECT_TRUE(dir.entries().empty()) << test::joined(dir.entries());
}

// ---- frames and regions ------------------------------------------------------------

// Four regions rendered apart and merged: the whole render, bit for bit.
TEST(WhittedRender, RegionsMergeIntoTheWholeRenderBitForBit) {
    TempDir dir;
    const std::vector<std::string> size = {"--width", "61", "--height", "37",
                                           "--spp",   "2",  "--quiet"};
    ASSERT_EQ(
        runRender(test::appended({test::kSeedScenePath, "-o", (dir / "whole.exr").string()}, size))
            .exitCode,
        0);
    std::vector<std::string> parts;
    for (const char* region : {"0,0,30,20", "30,0,61,20", "0,20,40,37", "40,20,61,37"}) {
        const fs::path part = dir / (std::string("part ") + region + ".exr");
        const ProgramRun r = runRender(
            test::appended({test::kSeedScenePath, "-o", part.string(), "--region", region}, size));
        ASSERT_EQ(r.exitCode, 0) << region << "\n" << describe(r);
        parts.push_back(part.string());
    }
    auto mergeArgs = [](std::vector<std::string> files, const fs::path& out) {
        files.insert(files.begin(), "merge");
        files.insert(files.end(), {"-o", out.string(), "--quiet"});
        return files;
    };
    const ProgramRun merged = runRender(mergeArgs(parts, dir / "merged.exr"));
    ASSERT_EQ(merged.exitCode, 0) << describe(merged);
    EXPECT_TRUE(test::samePixels(readImage(dir / "merged.exr"), readImage(dir / "whole.exr")));
    // A region's file is the region only, and says where it belongs.
    const ImagePart part = readImagePart(dir / "part 30,0,61,20.exr");
    EXPECT_EQ(part.image.width, 31);
    EXPECT_EQ(part.window.x, 30);
    EXPECT_EQ(part.fullWidth, 61);

    // Without one of the parts the merge refuses, naming the first missing pixel.
    const fs::path gap = dir / "gap.png";
    const ProgramRun refused = runRender(mergeArgs({parts[0], parts[2], parts[3]}, gap));
    EXPECT_EQ(refused.exitCode, 2) << describe(refused);
    EXPECT_NE(refused.err.find("pixel (30, 0)"), std::string::npos) << refused.err;
    EXPECT_FALSE(fs::exists(gap));
}

TEST(WhittedRender, BadRegionOrFrames_ExitTwoAndWriteNothing) {
    TempDir dir;
    const std::string exr = (dir / "o.exr").string(), png = (dir / "o.png").string();
    const std::vector<std::vector<std::string>> cases = {
        {"-o", exr, "--region", "0,0,700,10"},  // the seed is 640x480
        {"-o", exr, "--region", "5,5,5,9"},
        {"-o", exr, "--region", "1,2,3"},
        {"-o", png, "--region", "0,0,8,8"},  // a region needs OpenEXR
        {"-o", png, "--frames", "1-2"},      // frames need a turntable
        {"-o", png, "--turntable", "3", "--frames", "2-4"},
        {"-o", png, "--turntable", "3", "--frames", "2"},
        {"-o", png, "--turntable", "0"},
    };
    for (auto args : cases) {
        args.insert(args.begin(), test::kSeedScenePath);
        const ProgramRun r = runRender(args);
        std::string label;
        for (const auto& a : args) label += a + " ";
        EXPECT_EQ(r.exitCode, 2) << label << describe(r);
        EXPECT_FALSE(r.err.empty()) << label;
    }
    EXPECT_TRUE(dir.entries().empty()) << test::joined(dir.entries());
}

// A turntable writes numbered frames; frame 1 is the still, and a frame
// rendered alone (--frames) equals the same frame of the whole run.
TEST(WhittedRender, TurntableWritesNumberedFramesAndFramesRenderAlike) {
    TempDir dir;
    const std::vector<std::string> size = {"--width", "40", "--height", "30", "--quiet"};
    ASSERT_EQ(
        runRender(test::appended({test::kSeedScenePath, "-o", (dir / "still.png").string()}, size))
            .exitCode,
        0);
    const ProgramRun all = runRender(test::appended(
        {test::kSeedScenePath, "-o", (dir / "spin.exr").string(), "--turntable", "3"}, size));
    ASSERT_EQ(all.exitCode, 0) << describe(all);
    const ProgramRun some =
        runRender(test::appended({test::kSeedScenePath, "-o", (dir / "again.exr").string(),
                                  "--turntable", "3", "--frames", "3-3"},
                                 size));
    ASSERT_EQ(some.exitCode, 0) << describe(some);
    EXPECT_EQ(test::joined(dir.entries()),
              "[again.0003.exr, spin.0001.exr, spin.0002.exr, spin.0003.exr, still.png]");
    const Image first = readImage(dir / "spin.0001.exr"), second = readImage(dir / "spin.0002.exr");
    EXPECT_TRUE(
        test::samePixels(readImage(dir / "again.0003.exr"), readImage(dir / "spin.0003.exr")));
    EXPECT_FALSE(test::samePixels(first, second)) << "the camera did not turn";
    // The still as PNG against frame 1 as float, both through 8-bit sRGB.
    const Image still = readImage(dir / "still.png");
    int differing = 0;
    for (std::size_t i = 0; i < still.rgb.size(); ++i)
        differing += std::abs(still.rgb[i] - std::min(1.0f, std::max(0.0f, first.rgb[i]))) > 0.01f;
    EXPECT_EQ(differing, 0);
}

// ---- other failures: exit 1 -------------------------------------------------------

TEST(WhittedRender, UnwritableOutput_ExitsOneAndLeavesNoFile) {
    TempDir dir;
    const fs::path out = dir / "no such dir" / "o.png";
    const ProgramRun r = runRender(
        {test::kSeedScenePath, "-o", out.string(), "--width", "8", "--height", "8", "--quiet"});
    EXPECT_EQ(r.exitCode, 1) << describe(r);
    EXPECT_NE(r.err.find("o.png"), std::string::npos) << r.err;
    EXPECT_TRUE(dir.entries().empty()) << test::joined(dir.entries());
}

TEST(WhittedRender, UnwritableStats_ExitsOneAndRemovesTheImage) {
    TempDir dir;
    const fs::path out = dir / "o.png", stats = dir / "no such dir" / "stats.json";
    const ProgramRun r = runRender({test::kSeedScenePath, "-o", out.string(), "--width", "8",
                                    "--height", "8", "--stats", stats.string(), "--quiet"});
    EXPECT_EQ(r.exitCode, 1) << describe(r);
    // The file the user named and the system's reason, not a temporary's name.
    EXPECT_EQ(r.err, "whitted-render: " + stats.string() + ": No such file or directory\n");
    EXPECT_TRUE(dir.entries().empty()) << test::joined(dir.entries());
}

// ---- a pixel's ray tree ------------------------------------------------------------

// The sum of a tree's contributions, channel `c`.
double contributions(const nlohmann::json& node, int c) {
    double sum = node["contribution"][c].get<double>();
    for (const nlohmann::json& child : node["children"]) sum += contributions(child, c);
    return sum;
}

// What a user runs to see why a pixel looks as it does: the tree on stdout,
// its value the pixel a one-sample render writes, and no file anywhere.
TEST(WhittedRender, Inspect_PrintsThePixelsTreeWhoseValueIsTheRenderedPixel) {
    TempDir dir;
    const std::vector<std::string> size = {"--width", "64", "--height", "48", "--depth", "4"};
    for (const char* precision : {"float", "double"}) {
        std::vector<std::string> args = {test::kSeedScenePath, "--inspect", "20,30", "--precision",
                                         precision};
        args.insert(args.end(), size.begin(), size.end());
        const ProgramRun r = runRender(args);
        ASSERT_EQ(r.exitCode, 0) << describe(r);
        EXPECT_TRUE(dir.entries().empty()) << test::joined(dir.entries());
        const nlohmann::json tree = nlohmann::json::parse(r.out);
        EXPECT_EQ(tree["pixel"], nlohmann::json({20, 30}));
        const nlohmann::json& root = tree["rays"];
        EXPECT_EQ(root["kind"], "camera");
        EXPECT_EQ(root["weight"], 1.0);
        ASSERT_TRUE(root["hit"].is_string()) << root.dump();
        int shadows = 0;
        for (const nlohmann::json& child : root["children"]) shadows += child["kind"] == "shadow";
        EXPECT_EQ(shadows, 1) << "the seed has one light";

        const fs::path out = dir / "one.exr";
        args = {test::kSeedScenePath, "-o",     out.string(), "--spp", "1", "--quiet",
                "--precision",        precision};
        args.insert(args.end(), size.begin(), size.end());
        ASSERT_EQ(runRender(args).exitCode, 0);
        const Image image = readImage(out);
        fs::remove(out);
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(float(tree["value"][c].get<double>()), image.pixel(20, 30)[c])
                << precision << " channel " << c;
            EXPECT_NEAR(contributions(root, c), tree["value"][c].get<double>(), 1e-5)
                << precision << " channel " << c;
        }
    }
}

TEST(WhittedRender, InspectOutsideThePictureOrWithAnImage_ExitTwoSayingWhy) {
    TempDir dir;
    ProgramRun r =
        runRender({test::kSeedScenePath, "--inspect", "64,0", "--width", "64", "--height", "48"});
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_EQ(r.err, "whitted-render: --inspect: pixel 64,0 is outside the 64x48 picture\n");
    EXPECT_TRUE(r.out.empty()) << r.out;
    r = runRender({test::kSeedScenePath, "--inspect", "1,1", "-o", (dir / "o.png").string()});
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_NE(r.err.find("--inspect prints one pixel's ray tree and renders no image"),
              std::string::npos)
        << r.err;
    EXPECT_TRUE(dir.entries().empty()) << test::joined(dir.entries());
}

TEST(WhittedRender, SamplerWhitted1980_WritesTheCoresPictureItsStatsAndItsMap) {
    TempDir dir;
    const fs::path out = dir / "w.exr", stats = dir / "stats.json", map = dir / "map.png";
    const ProgramRun r =
        runRender({test::kSeedScenePath, "-o", out.string(), "--width", "64", "--height", "48",
                   "--sampler", "whitted1980", "--threshold", "6", "--subdivisions", "3", "--stats",
                   stats.string(), "--subdivision-map", map.string()});
    ASSERT_EQ(r.exitCode, 0) << describe(r);
    EXPECT_NE(r.err.find("Whitted 1980 sampling (threshold 6 codes, at most 3 subdivisions)"),
              std::string::npos)
        << r.err;

    RenderOptions options = oneShotOptions();
    options.whitted1980 = Whitted1980Sampling{6.0, 3};
    const RenderResult want = render(test::seedScene(64, 48), options);
    const Image written = readImage(out);
    EXPECT_TRUE(test::samePixels(written, want.image))
        << test::firstDifference(written, want.image);

    const nlohmann::json j = nlohmann::json::parse(test::readFile(stats));
    EXPECT_FALSE(j.contains("samples_per_pixel")) << j.dump(2);
    EXPECT_EQ(j["sampler"]["name"], "whitted1980");
    EXPECT_EQ(j["sampler"]["threshold"], 6.0);
    EXPECT_EQ(j["sampler"]["subdivisions"], 3);
    EXPECT_EQ(j["rays"]["camera"].get<std::uint64_t>(), want.rays.camera);
    EXPECT_DOUBLE_EQ(j["sampler"]["camera_rays_per_pixel"].get<double>(),
                     double(want.rays.camera) / (64 * 48));
    const auto atDepth = j["sampler"]["pixels_at_each_depth"].get<std::vector<long long>>();
    ASSERT_EQ(atDepth.size(), 4u);
    for (int level = 0; level <= 3; ++level)
        EXPECT_EQ(atDepth[level],
                  std::count(want.subdivision.levels.begin(), want.subdivision.levels.end(), level))
            << level;

    // The map: black where a pixel was not cut, pale yellow where cut three times.
    const Image shown = readImage(map);
    ASSERT_EQ(shown.width, 64);
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x) {
            const float* p = shown.pixel(x, y);
            if (want.subdivision.at(x, y) == 0) {
                EXPECT_EQ(p[0] + p[1] + p[2], 0.0f) << x << "," << y;
            }
            if (want.subdivision.at(x, y) == 3) {
                EXPECT_GT(p[1], 0.9f) << x << "," << y;
            }
        }
}

TEST(WhittedRender, SamplerFlagsThatDoNotGo_ExitTwoAndWriteNothing) {
    TempDir dir;
    const std::string out = (dir / "o.png").string();
    ProgramRun r =
        runRender({test::kSeedScenePath, "-o", out, "--sampler", "whitted1980", "--spp", "4"});
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_NE(r.err.find("--sampler whitted1980 chooses its own rays"), std::string::npos) << r.err;
    r = runRender({test::kSeedScenePath, "-o", out, "--threshold", "4"});
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_NE(r.err.find("need --sampler whitted1980"), std::string::npos) << r.err;
    r = runRender(
        {test::kSeedScenePath, "-o", out, "--sampler", "whitted1980", "--subdivisions", "7"});
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    r = runRender({test::kSeedScenePath, "-o", out, "--sampler", "whitted1981"});
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_TRUE(dir.entries().empty()) << test::joined(dir.entries());
}

// A program copied away from the image plug-in it is installed with still
// writes PNG and OpenEXR (libpng and OpenEXR, linked in), and for the other
// formats renders, then says what it could not load instead of writing the
// picture.
TEST(WhittedRender, WithoutItsImagePlugin_WritesPngAndExrAndSaysWhyNotTiff) {
    TempDir dir;
    fs::create_directory(dir / "bin");
    const fs::path program = dir / "bin" / "whitted-render", tiff = dir / "o.tif";
    fs::copy_file(WHITTED_RENDER_EXE, program);
    const auto run = [&](const fs::path& out) {
        return test::Program{program.string()}(
            {test::kSeedScenePath, "-o", out.string(), "--width", "8", "--height", "8", "--quiet"});
    };
    for (const char* name : {"o.png", "o.exr"}) {
        const ProgramRun wrote = run(dir / name);
        EXPECT_EQ(wrote.exitCode, 0) << name << ": " << describe(wrote);
        EXPECT_EQ(readImage(dir / name).width, 8) << name;
    }
    const ProgramRun r = run(tiff);
    EXPECT_EQ(r.exitCode, 1) << describe(r);
    EXPECT_NE(r.err.find(tiff.string() + ": cannot load the image library: "), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("whitted_oiio.so"), std::string::npos) << r.err;
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"bin", "o.exr", "o.png"}))
        << test::joined(dir.entries());
}

// OpenImageIO's libraries load with the first image file that needs them, not
// with the program (core/image/image_codec.h): a run that writes a PNG or an
// OpenEXR file, or no image, or merges OpenEXR parts, never binds them; one
// that writes a TIFF does.
TEST(WhittedRender, LoadsOpenImageIOOnlyForFormatsBesidesPngAndExr) {
    TempDir dir;
    const ProgramRun refused = runRender(
        {test::kSeedScenePath, "-o", (dir / "o.png").string(), "--spp", "0"}, "LD_DEBUG=files");
    EXPECT_EQ(refused.exitCode, 2) << describe(refused);
    EXPECT_EQ(refused.err.find("libOpenImageIO"), std::string::npos) << refused.err;
    const auto write = [&](const char* name) {
        return runRender({test::kSeedScenePath, "-o", (dir / name).string(), "--width", "8",
                          "--height", "8", "--quiet"},
                         "LD_DEBUG=files");
    };
    for (const char* name : {"o.png", "o.exr"}) {
        const ProgramRun wrote = write(name);
        EXPECT_EQ(wrote.exitCode, 0) << name << ": " << describe(wrote);
        EXPECT_TRUE(fs::exists(dir / name)) << name;
        EXPECT_EQ(wrote.err.find("libOpenImageIO"), std::string::npos) << name;
    }
    const ProgramRun merged =
        runRender({"merge", (dir / "o.exr").string(), "-o", (dir / "m.exr").string(), "--quiet"},
                  "LD_DEBUG=files");
    EXPECT_EQ(merged.exitCode, 0) << describe(merged);
    EXPECT_TRUE(test::samePixels(readImage(dir / "m.exr"), readImage(dir / "o.exr")));
    EXPECT_EQ(merged.err.find("libOpenImageIO"), std::string::npos) << "merge";
    const ProgramRun wroteTiff = write("o.tif");
    EXPECT_EQ(wroteTiff.exitCode, 0) << describe(wroteTiff);
    EXPECT_NE(wroteTiff.err.find("whitted_oiio.so"), std::string::npos);
    EXPECT_NE(wroteTiff.err.find("libOpenImageIO"), std::string::npos);
}

// ---- rendering to a quality --------------------------------------------------

TEST(WhittedRender, QualityFinal_MeetsItsTargetAgainstAConvergedRenderAndSaysWhy) {
    TempDir dir;
    const fs::path out = dir / "final.exr", ref = dir / "ref.exr", stats = dir / "stats.json";
    const ProgramRun r =
        runRender({test::kSeedScenePath, "-o", out.string(), "--width", "128", "--height", "96",
                   "--quality", "final", "--stats", stats.string()});
    ASSERT_EQ(r.exitCode, 0) << describe(r);
    EXPECT_NE(r.err.find("quality Final: 50 dB, no pixel off by more than 16 codes"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("depth "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("samples: each tile until"), std::string::npos) << r.err;
    if (!test::kSanitized) {  // the numbers, which the Release stage checks
        const ProgramRun converged =
            runRender({test::kSeedScenePath, "-o", ref.string(), "--width", "128", "--height", "96",
                       "--spp", "1024", "--depth", "12", "--precision", "double", "--quiet"});
        ASSERT_EQ(converged.exitCode, 0) << describe(converged);
        const ErrorStats e = measureError(readImage(out), readImage(ref));
        EXPECT_GE(e.psnrSrgb8, 50.0);
        EXPECT_LE(e.largest, 16.0);
    }

    const nlohmann::json j = nlohmann::json::parse(test::readFile(stats));
    ASSERT_TRUE(j.contains("quality")) << j.dump(2);
    const auto& q = j["quality"];
    EXPECT_EQ(q["target"], "Final");
    EXPECT_EQ(q["target_psnr_db"], 50.0);
    EXPECT_EQ(q["target_max_error_codes"], 16.0);
    EXPECT_EQ(q["depth_chosen"], true);
    // Measured three levels deeper in the probe; at the picture's own size,
    // against depth 64, the deepest SPEC allows, where light trapped in
    // glass may still come out.
    const int depth = j["max_depth"].get<int>();
    EXPECT_EQ(q["reference_depth"].get<int>(),
              q["depth_measured_at_picture_size"].get<bool>() ? 64 : depth + 3);
    // Sampled where the picture needs it: the flat background stops early.
    EXPECT_LT(q["samples_per_pixel_fewest"].get<int>(), q["samples_per_pixel_most"].get<int>());
    EXPECT_GE(q["estimated_psnr_db"].get<double>(), 50.0);
    EXPECT_EQ(q["tiles_at_sample_limit"], 0);

    // The file says what the render did, not the scene's samples_per_pixel.
    const ImageMetadata m = readImagePart(out).metadata;
    EXPECT_EQ(m.settings.maxDepth, j["max_depth"].get<int>());
    EXPECT_EQ(m.settings.samplesPerPixel, q["samples_per_pixel_most"].get<int>());
    const std::string samples = std::to_string(q["samples_per_pixel_fewest"].get<int>()) + " to " +
                                std::to_string(q["samples_per_pixel_most"].get<int>()) +
                                " samples a pixel";
    EXPECT_EQ(m.qualityTarget, "Final: 50 dB, no pixel off by more than 16 codes");
    EXPECT_EQ(m.qualityReached.rfind(
                  "depth " + std::to_string(j["max_depth"].get<int>()) + ", " + samples, 0),
              0u)
        << m.qualityReached;
    EXPECT_NE(m.description.find("to a quality, Final: 50 dB"), std::string::npos) << m.description;
}

// Draft is loose enough that one sample at each pixel's centre may do: where
// the picture's estimate says it does, the render is the one-sample render at
// the chosen depth, pixel for pixel, and still meets 20 dB.
TEST(WhittedRender, QualityDraft_TracesThePixelCentresAndStopsThereWhereThatMeetsIt) {
    TempDir dir;
    const fs::path out = dir / "draft.exr", one = dir / "one.exr", ref = dir / "ref.exr",
                   stats = dir / "stats.json";
    const std::vector<std::string> size = {"--width", "320", "--height", "240"};
    auto args = [&](std::vector<std::string> list) {
        list.insert(list.begin() + 1, size.begin(), size.end());
        return list;
    };
    const ProgramRun r = runRender(args({test::kSeedScenePath, "-o", out.string(), "--quality",
                                         "draft", "--stats", stats.string()}));
    ASSERT_EQ(r.exitCode, 0) << describe(r);
    EXPECT_NE(r.err.find("samples: one at each pixel's centre, its error estimated from "
                         "neighbouring pixels"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("reached: 1 sample a pixel everywhere"), std::string::npos) << r.err;
    const nlohmann::json j = nlohmann::json::parse(test::readFile(stats));
    EXPECT_EQ(j["quality"]["samples_per_pixel_most"], 1) << j.dump(2);
    const std::string depth = std::to_string(j["max_depth"].get<int>());
    const ProgramRun fixed = runRender(args(
        {test::kSeedScenePath, "-o", one.string(), "--spp", "1", "--depth", depth, "--quiet"}));
    ASSERT_EQ(fixed.exitCode, 0) << describe(fixed);
    const Image draft = readImage(out);
    EXPECT_EQ(draft.rgb, readImage(one).rgb) << "not the one-sample render at depth " << depth;
    if (test::kSanitized) return;  // the numbers, which the Release stage checks
    const ProgramRun converged =
        runRender(args({test::kSeedScenePath, "-o", ref.string(), "--spp", "256", "--depth", "12",
                        "--precision", "double", "--quiet"}));
    ASSERT_EQ(converged.exitCode, 0) << describe(converged);
    EXPECT_GE(measureError(draft, readImage(ref)).psnrSrgb8, 20.0);
}

TEST(WhittedRender, TargetPsnr_IsMetAndAGivenDepthIsKept) {
    TempDir dir;
    const fs::path out = dir / "t.exr", ref = dir / "ref.exr", stats = dir / "stats.json";
    const ProgramRun r =
        runRender({test::kSeedScenePath, "-o", out.string(), "--width", "48", "--height", "36",
                   "--target-psnr", "40", "--depth", "6", "--stats", stats.string(), "--quiet"});
    ASSERT_EQ(r.exitCode, 0) << describe(r);
    EXPECT_EQ(r.err, "");
    if (!test::kSanitized) {  // the numbers, which the Release stage checks
        const ProgramRun converged =
            runRender({test::kSeedScenePath, "-o", ref.string(), "--width", "48", "--height", "36",
                       "--spp", "1024", "--depth", "12", "--precision", "double", "--quiet"});
        ASSERT_EQ(converged.exitCode, 0) << describe(converged);
        EXPECT_GE(measureError(readImage(out), readImage(ref)).psnrSrgb8, 40.0);
    }
    const nlohmann::json j = nlohmann::json::parse(test::readFile(stats));
    EXPECT_EQ(j["max_depth"], 6);
    EXPECT_EQ(j["quality"]["target"], "custom");
    EXPECT_EQ(j["quality"]["depth_chosen"], false);
    EXPECT_TRUE(j["quality"]["target_max_error_codes"].is_null());
}

// A farm renders a quality in regions (whitted-farm --quality): each region
// planned as the whole picture is, and sampled until it meets the target
// itself, so that the merged picture meets it too; the merged file says what
// each part reached. A part of fixed samples is another render's.
TEST(WhittedRender, RegionsToAQuality_MergeIntoAPictureThatMeetsIt) {
    TempDir dir;
    const std::vector<std::string> size = {"--width", "96", "--height", "72"};
    std::vector<std::string> parts;
    int mostSamples = 0;
    for (const char* region : {"0,0,48,36", "48,0,96,36", "0,36,48,72", "48,36,96,72"}) {
        const fs::path part = dir / (std::string("part ") + region + ".exr");
        const ProgramRun r =
            runRender(test::appended({test::kSeedScenePath, "-o", part.string(), "--quality",
                                      "final", "--region", region, "--quiet"},
                                     size));
        ASSERT_EQ(r.exitCode, 0) << region << "\n" << describe(r);
        parts.push_back(part.string());
        mostSamples = std::max(mostSamples, readImagePart(part).metadata.settings.samplesPerPixel);
    }
    const fs::path merged = dir / "merged.exr", ref = dir / "ref.exr";
    ProgramRun r =
        runRender(test::appended({"merge"}, test::appended(parts, {"-o", merged.string()})));
    ASSERT_EQ(r.exitCode, 0) << describe(r);
    if (!test::kSanitized) {  // the numbers, which the Release stage checks
        ASSERT_EQ(
            runRender(test::appended({test::kSeedScenePath, "-o", ref.string(), "--spp", "1024",
                                      "--depth", "12", "--precision", "double", "--quiet"},
                                     size))
                .exitCode,
            0);
        const ErrorStats e = measureError(readImage(merged), readImage(ref));
        EXPECT_GE(e.psnrSrgb8, 50.0);
        EXPECT_LE(e.largest, 16.0);
    }
    const ImageMetadata m = readImagePart(merged).metadata;
    EXPECT_EQ(m.qualityTarget, "Final: 50 dB, no pixel off by more than 16 codes");
    EXPECT_EQ(m.qualityReached.rfind("4 regions, each rendered to it: depth ", 0), 0u)
        << m.qualityReached;
    EXPECT_NE(m.description.find("to a quality, Final: 50 dB, no pixel off by more than 16 "
                                 "codes; 4 regions"),
              std::string::npos)
        << m.description;
    EXPECT_EQ(m.settings.samplesPerPixel, mostSamples);

    const fs::path fixed = dir / "fixed.exr", mixed = dir / "mixed.exr";
    ASSERT_EQ(runRender(test::appended({test::kSeedScenePath, "-o", fixed.string(), "--region",
                                        "48,36,96,72", "--quiet"},
                                       size))
                  .exitCode,
              0);
    r = runRender({"merge", parts[0], parts[1], parts[2], fixed.string(), "-o", mixed.string()});
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_NE(r.err.find(fixed.string() + " was rendered to fixed samples, " + parts[0] +
                         " to a quality (Final: 50 dB, no pixel off by more than 16 codes)"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(mixed));
}

// --plan: the first region plans and writes the file, the others render to
// it without planning (a plan edited by hand shows that it is read); a plan
// for another picture, or without a quality, is refused.
TEST(WhittedRender, PlanFile_MadeOnceThenReadByEachRegion) {
    TempDir dir;
    const fs::path planFile = dir / "plan.json";
    const auto region = [&](const char* corners, const std::vector<std::string>& more = {}) {
        const fs::path part = dir / (std::string("part ") + corners + ".exr");
        return runRender(
            test::appended({test::kSeedScenePath, "-o", part.string(), "--width", "96", "--height",
                            "72", "--quality", "preview", "--region", corners, "--plan",
                            planFile.string(), "--stats", (dir / "stats.json").string()},
                           more));
    };
    ProgramRun r = region("0,0,48,72");
    ASSERT_EQ(r.exitCode, 0) << describe(r);
    EXPECT_EQ(r.err.find("the plan in "), std::string::npos) << r.err;  // made, not read
    nlohmann::json plan = nlohmann::json::parse(test::readFile(planFile));
    EXPECT_EQ(plan["target"], "Preview");
    EXPECT_EQ(plan["max_depth"],
              nlohmann::json::parse(test::readFile(dir / "stats.json"))["max_depth"]);
    plan["max_depth"] = 1;
    test::writeFile(planFile, plan.dump());
    r = region("48,0,96,72");
    ASSERT_EQ(r.exitCode, 0) << describe(r);
    EXPECT_NE(r.err.find("the plan in " + planFile.string() + ", made before for this picture:"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(nlohmann::json::parse(test::readFile(dir / "stats.json"))["max_depth"], 1);
    EXPECT_NE(r.err.find(": region 48,0,96,72 of 96x72, "), std::string::npos) << r.err;

    r = runRender({test::kSeedScenePath, "-o", (dir / "small.exr").string(), "--width", "64",
                   "--height", "48", "--quality", "preview", "--region", "0,0,8,8", "--plan",
                   planFile.string()});
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_NE(r.err.find(planFile.string() +
                         ": the plan is for a picture of 96x72 in float, this one is 64x48 in "
                         "float"),
              std::string::npos)
        << r.err;
    r = runRender({test::kSeedScenePath, "-o", (dir / "other.exr").string(), "--width", "96",
                   "--height", "72", "--target-psnr", "40", "--region", "0,0,8,8", "--plan",
                   planFile.string()});
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_NE(r.err.find(": the plan is for Preview: 35 dB, no pixel off by more than 64 codes, "
                         "not 40 dB"),
              std::string::npos)
        << r.err;
    // Without --output it only plans (whitted-farm's plan job).
    const fs::path planOnly = dir / "plan only.json";
    r = runRender({test::kSeedScenePath, "--width", "96", "--height", "72", "--quality", "preview",
                   "--plan", planOnly.string()});
    ASSERT_EQ(r.exitCode, 0) << describe(r);
    EXPECT_NE(r.err.find("quality Preview: 35 dB"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("wrote " + planOnly.string()), std::string::npos) << r.err;
    EXPECT_EQ(nlohmann::json::parse(test::readFile(planOnly))["target"], "Preview");
    r = runRender({test::kSeedScenePath, "--quality", "preview", "--region", "0,0,8,8", "--plan",
                   (dir / "refused plan.json").string()});
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_NE(r.err.find("--plan without --output only plans"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "refused plan.json"));

    // The same size and target, another scene: its plan would be the seed's.
    r = runRender({WHITTED_SCENES_DIR "/glass.json", "-o", (dir / "glass.exr").string(), "--width",
                   "96", "--height", "72", "--quality", "preview", "--region", "0,0,8,8", "--plan",
                   planFile.string()});
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_NE(r.err.find(planFile.string() + ": the plan is for another scene"), std::string::npos)
        << r.err;
    r = runRender(
        {test::kSeedScenePath, "-o", (dir / "fixed.png").string(), "--plan", planFile.string()});
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_NE(r.err.find("--plan needs --quality or --target-psnr"), std::string::npos) << r.err;
    // The plan only, for another scene: refused the same way.
    r = runRender({WHITTED_SCENES_DIR "/glass.json", "--width", "96", "--height", "72", "--quality",
                   "preview", "--plan", planFile.string()});
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_NE(r.err.find(planFile.string() + ": the plan is for another scene"), std::string::npos)
        << r.err;
    // A plan file that cannot be written is the system's failure, not the user's.
    const fs::path nowhere = dir / "no such folder" / "plan.json";
    for (const bool withOutput : {false, true}) {
        std::vector<std::string> args{
            test::kSeedScenePath, "--width", "96",     "--height",      "72",
            "--quality",          "preview", "--plan", nowhere.string()};
        if (withOutput) args.insert(args.end(), {"-o", (dir / "unplanned.exr").string()});
        r = runRender(args);
        EXPECT_EQ(r.exitCode, 1) << describe(r);
        EXPECT_NE(r.err.find("whitted-render: " + nowhere.string() +
                             ": cannot write the plan: No such file or directory\n"),
                  std::string::npos)
            << r.err;
    }
    for (const char* refused :
         {"small.exr", "other.exr", "glass.exr", "fixed.png", "unplanned.exr"})
        EXPECT_FALSE(fs::exists(dir / refused)) << refused;
}

TEST(WhittedRender, QualityFlagsThatContradict_ExitTwoAndWriteNothing) {
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"--quality", "best"}, "--quality"},
        {{"--quality", "final", "--target-psnr", "40"}, "give one or the other"},
        {{"--max-error", "8"}, "--max-error needs --target-psnr"},
        {{"--target-psnr", "0"}, "--target-psnr"},
    };
    for (const auto& [flags, message] : cases) {
        TempDir dir;
        std::vector<std::string> args = {test::kSeedScenePath, "-o", (dir / "x.png").string()};
        args.insert(args.end(), flags.begin(), flags.end());
        const ProgramRun r = runRender(args);
        EXPECT_EQ(r.exitCode, 2) << test::joined(flags) << "\n" << describe(r);
        EXPECT_NE(r.err.find(message), std::string::npos) << test::joined(flags) << "\n" << r.err;
        EXPECT_TRUE(dir.entries().empty()) << test::joined(dir.entries());
    }
}

}  // namespace
}  // namespace whitted
