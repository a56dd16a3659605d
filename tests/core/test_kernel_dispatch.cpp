// Tests for core/kernel_dispatch.*: the tracer's per-instruction-set kernels
// render the same images bit for bit, the dispatcher picks the widest one the
// CPU runs, and a kernel that is unknown or that the CPU lacks is refused with
// a message instead of crashing.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "image/image_io.h"
#include "scene/scene_io.h"
#include "support/core_support.h"
#include "support/test_support.h"
#include "tracer/kernel_dispatch.h"
#include "tracer/renderer.h"

namespace whitted {
namespace {

bool contains(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

// The message of what `action` throws, or "" when it throws nothing.
template <typename Action>
std::string refusal(Action action) {
    try {
        action();
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

// Every test starts and ends with the automatic choice and no WHITTED_KERNEL.
class KernelDispatch : public ::testing::Test {
  protected:
    void SetUp() override { resetChoice(); }
    void TearDown() override { resetChoice(); }
    static void resetChoice() {
        unsetenv("WHITTED_KERNEL");
        useKernel("");
    }
};

TEST_F(KernelDispatch, BuildsEveryInstructionSetWidestFirst) {
    std::vector<std::string> expected = {"avx512", "avx2_zen", "avx2", "sse4", "baseline"};
    if (contains(builtKernelNames(), "native")) expected.insert(expected.begin(), "native");
    EXPECT_EQ(builtKernelNames(), expected);
}

TEST_F(KernelDispatch, SupportedKernelsAreWhatTheCpuReports) {
    __builtin_cpu_init();
    const std::vector<std::string> supported = supportedKernelNames();
    EXPECT_EQ(contains(supported, "avx512"), __builtin_cpu_supports("x86-64-v4") != 0);
    EXPECT_EQ(contains(supported, "avx2"), __builtin_cpu_supports("x86-64-v3") != 0);
    EXPECT_EQ(contains(supported, "avx2_zen"), __builtin_cpu_supports("x86-64-v3") != 0);
    EXPECT_EQ(contains(supported, "sse4"), __builtin_cpu_supports("x86-64-v2") != 0);
    EXPECT_TRUE(contains(supported, "baseline"));
    EXPECT_EQ(contains(supported, "native"), contains(builtKernelNames(), "native"));
}

TEST_F(KernelDispatch, PicksTheWidestSupportedKernel) {
    __builtin_cpu_init();
    std::string widest = "baseline";
    if (__builtin_cpu_supports("x86-64-v2")) widest = "sse4";
    if (__builtin_cpu_supports("x86-64-v3")) widest = __builtin_cpu_is("amd") ? "avx2_zen" : "avx2";
    if (__builtin_cpu_supports("x86-64-v4")) widest = "avx512";
    if (contains(builtKernelNames(), "native")) widest = "native";  // the build's own flags
    EXPECT_EQ(widestSupportedKernelName(), widest);
    EXPECT_EQ(activeKernelName(), widest);
}

TEST_F(KernelDispatch, DescriptionsNameTheInstructionSetAndWidth) {
    useKernel("baseline");
    EXPECT_EQ(activeKernelName(), "baseline");
    EXPECT_EQ(activeKernelDescription(), "baseline (-march=x86-64, 4 floats per packet)");
    if (!contains(supportedKernelNames(), "avx2")) GTEST_SKIP() << "this CPU has no AVX2";
    useKernel("avx2");
    EXPECT_EQ(activeKernelName(), "avx2");
    EXPECT_EQ(activeKernelDescription(), "avx2 (-march=x86-64-v3, 8 floats per packet)");
    useKernel("avx2_zen");
    EXPECT_EQ(activeKernelDescription(),
              "avx2_zen (-march=x86-64-v3 -mtune=znver3, 8 floats per packet)");
}

TEST_F(KernelDispatch, RefusesAnUnknownKernelAndKeepsTheActiveOne) {
    useKernel("baseline");
    const std::string message = refusal([] { useKernel("sse9"); });
    std::printf("refused: %s\n", message.c_str());
    EXPECT_NE(message.find("\"sse9\""), std::string::npos) << message;
    EXPECT_NE(message.find("avx512, avx2_zen, avx2, sse4, baseline"), std::string::npos) << message;
    EXPECT_EQ(activeKernelName(), "baseline");
}

TEST_F(KernelDispatch, RefusesAKernelTheCpuLacks) {
    std::string missing;
    for (const std::string& name : builtKernelNames())
        if (!contains(supportedKernelNames(), name)) missing = name;
    if (missing.empty()) GTEST_SKIP() << "this CPU runs every kernel built";
    const std::string message = refusal([&] { useKernel(missing); });
    std::printf("refused: %s\n", message.c_str());
    EXPECT_NE(message.find("\"" + missing + "\" needs x86-64-v"), std::string::npos) << message;
    EXPECT_NE(message.find("this CPU lacks"), std::string::npos) << message;
    EXPECT_NE(activeKernelName(), missing);
}

TEST_F(KernelDispatch, EnvironmentVariableForcesAKernel) {
    setenv("WHITTED_KERNEL", "baseline", 1);
    useKernel("");
    EXPECT_EQ(activeKernelName(), "baseline");
    setenv("WHITTED_KERNEL", "sse9", 1);
    const std::string message = refusal([] { useKernel(""); });
    std::printf("refused: %s\n", message.c_str());
    EXPECT_EQ(message.rfind("WHITTED_KERNEL: no tracer kernel is named \"sse9\"", 0), 0u)
        << message;
}

// whitted-render run with one environment variable set ("NAME=value"): its
// exit status (-1 for a signal, SIGILL included) and everything it printed.
test::ProgramRun renderWith(const std::string& variable, const std::filesystem::path& image) {
    return test::runProgram(
        WHITTED_RENDER_EXE,
        {test::kSeedScenePath, "--quiet", "--width", "16", "--height", "12", "-o", image.string()},
        test::Stderr::Merged, variable);
}

TEST_F(KernelDispatch, WhittedRenderRefusesKernelsItCannotRun) {
    test::TempDir dir;
    std::vector<std::string> refused = {"sse9"};
    for (const std::string& name : builtKernelNames())
        if (!contains(supportedKernelNames(), name)) refused.push_back(name);
    for (const std::string& kernel : refused) {
        const test::ProgramRun run = renderWith("WHITTED_KERNEL=" + kernel, dir.path() / "out.png");
        std::printf("WHITTED_KERNEL=%s: exit %d, %s", kernel.c_str(), run.exitCode,
                    run.out.c_str());
        EXPECT_EQ(run.exitCode, 2) << run.out;
        EXPECT_NE(run.out.find("WHITTED_KERNEL: "), std::string::npos) << run.out;
        EXPECT_NE(run.out.find("\"" + kernel + "\""), std::string::npos) << run.out;
        EXPECT_FALSE(std::filesystem::exists(dir.path() / "out.png"));
    }
    const test::ProgramRun baseline = renderWith("WHITTED_KERNEL=baseline", dir.path() / "out.png");
    EXPECT_EQ(baseline.exitCode, 0) << baseline.out;
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "out.png"));
}

// WHITTED_ACCEL is refused like WHITTED_KERNEL when it names no structure; a
// forced BVH renders the seed to the same file as its own brute force.
TEST_F(KernelDispatch, WhittedRenderRefusesAnUnknownAcceleration) {
    test::TempDir dir;
    const test::ProgramRun bad = renderWith("WHITTED_ACCEL=octree", dir.path() / "out.png");
    EXPECT_EQ(bad.exitCode, 2) << bad.out;
    EXPECT_NE(bad.out.find("WHITTED_ACCEL: unknown value 'octree'"), std::string::npos) << bad.out;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "out.png"));
    ASSERT_EQ(renderWith("WHITTED_ACCEL=bvh", dir.path() / "bvh.png").exitCode, 0);
    ASSERT_EQ(renderWith("WHITTED_ACCEL=brute", dir.path() / "brute.png").exitCode, 0);
    EXPECT_EQ(test::firstDifference(readImage(dir.path() / "bvh.png"),
                                    readImage(dir.path() / "brute.png")),
              "");
}

// Renders of the repository's scenes, one per kernel this CPU runs.
struct SceneCase {
    const char* file;
    Precision precision;
};

class KernelsRenderAlike : public KernelDispatch,
                           public ::testing::WithParamInterface<SceneCase> {};

RenderResult renderWith(const std::string& kernel, const Scene& scene) {
    useKernel(kernel);
    RenderOptions options;
    options.progressive = false;
    return render(scene, options);
}

TEST_P(KernelsRenderAlike, BitForBit) {
    const std::vector<std::string> kernels = supportedKernelNames();
    if (kernels.size() < 2) GTEST_SKIP() << "this CPU runs one kernel: nothing to compare";
    Scene scene = loadScene(std::string(WHITTED_SCENES_DIR "/") + GetParam().file);
    scene.render.precision = GetParam().precision;
    // Half size: every material and path stays in the picture, and glass in
    // double with every kernel fits the sanitizer runs' timeout on a busy CI
    // machine (55 s of 120 alone under ASan at full size).
    scene.render.width /= 2;
    scene.render.height /= 2;
    const RenderResult reference = renderWith(kernels.back(), scene);
    for (std::size_t k = 0; k + 1 < kernels.size(); ++k) {
        const RenderResult other = renderWith(kernels[k], scene);
        EXPECT_EQ(test::firstDifference(other.image, reference.image), "")
            << kernels[k] << " against " << kernels.back();
        EXPECT_EQ(other.rays.total(), reference.rays.total()) << kernels[k];
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, KernelsRenderAlike,
                         ::testing::Values(SceneCase{"seed.json", Precision::Float},
                                           SceneCase{"seed.json", Precision::Double},
                                           SceneCase{"glass.json", Precision::Float},
                                           SceneCase{"glass.json", Precision::Double}),
                         [](const auto& info) {
                             std::string name = info.param.file;
                             name = name.substr(0, name.find('.'));
                             return name + "_" + std::string(precisionName(info.param.precision));
                         });

}  // namespace
}  // namespace whitted
