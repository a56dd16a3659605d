// End-to-end tests of whitted-tradeoff: a --quick run on a small seed writes
// every file with the expected rows, the report mode chooses presets from it,
// and bad input exits 2 with a message naming the file or flag.
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scene/scene_io.h"
#include "support/core_support.h"
#include "support/test_support.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;
using test::ProgramRun;
using test::TempDir;

// whitted-tradeoff with the arguments, its stdout and stderr together in `out`.
const test::Program tradeoff{WHITTED_TRADEOFF_EXE, test::Stderr::Merged};

std::vector<std::string> lines(const fs::path& file) {
    std::ifstream in(file);
    std::vector<std::string> out;
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

TEST(WhittedTradeoff, QuickRun_WritesEveryFileWithOneRowPerPoint) {
    TempDir dir;
    saveScene(test::seedScene(64, 48), dir / "small.json");
    const fs::path out = dir / "out";
    const ProgramRun r =
        tradeoff({(dir / "small.json").string(), "--out-dir", out.string(), "--quick"});
    ASSERT_EQ(r.exitCode, 0) << r.out;
    for (const char* name :
         {"points.csv", "table.md", "plot.png", "progressive.csv", "progressive.png",
          "truncation.png", "reference.png", "summary.md", "summary.json"})
        EXPECT_TRUE(fs::is_regular_file(out / name)) << name;
    // --quick: samples {1, 4} x depths {0, 2} x float, double x scales {0.5, 1}.
    const std::vector<std::string> csv = lines(out / "points.csv");
    ASSERT_EQ(csv.size(), 1u + 16u);
    int front = 0;
    for (std::size_t i = 1; i < csv.size(); ++i) {
        EXPECT_EQ(std::count(csv[i].begin(), csv[i].end(), ','), 15) << csv[i];
        front += csv[i].back() == '1';
    }
    EXPECT_GE(front, 1);
    // The half-size rows render 32x24.
    EXPECT_EQ(csv[1].rfind("1,0,float,0.5,32,24,", 0), 0u) << csv[1];
    // The progressive curve, refining to --quick's 4 samples: preview, 1, 2, 4.
    const std::vector<std::string> curve = lines(out / "progressive.csv");
    ASSERT_EQ(curve.size(), 5u) << test::joined(curve);
    EXPECT_EQ(curve[0].rfind("pass,samples,seconds,", 0), 0u) << curve[0];
    EXPECT_EQ(curve[4].rfind("3,4,", 0), 0u) << curve[4];

    // The report over this run: presets and the scene's section.
    const ProgramRun rep =
        tradeoff({"--report", (dir / "tradeoff.md").string(), "--dirs", out.string()});
    ASSERT_EQ(rep.exitCode, 0) << rep.out;
    const std::string md = test::readFile(dir / "tradeoff.md");
    EXPECT_NE(md.find("| Draft |"), std::string::npos);
    EXPECT_NE(md.find("| Final |"), std::string::npos);
    EXPECT_NE(md.find("## small"), std::string::npos);  // the scene file's name
    EXPECT_NE(md.find("(out/plot.png)"), std::string::npos);
    EXPECT_NE(rep.out.find("Draft: "), std::string::npos) << rep.out;
}

TEST(WhittedTradeoff, WidthAndHeight_OverrideTheScenesSize) {
    TempDir dir;
    const fs::path out = dir / "out";
    const ProgramRun r =
        tradeoff({test::kSeedScenePath, "--out-dir", out.string(), "--width", "40", "--height",
                  "30", "--samples", "1", "--depths", "1", "--precisions", "float", "--scales", "1",
                  "--reference-spp", "4", "--progressive-spp", "1"});
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const std::vector<std::string> csv = lines(out / "points.csv");
    ASSERT_EQ(csv.size(), 2u);
    EXPECT_EQ(csv[1].rfind("1,1,float,1,40,30,", 0), 0u) << csv[1];
}

TEST(WhittedTradeoff, BadInput_ExitsTwoNamingTheProblem) {
    TempDir dir;
    ProgramRun r = tradeoff({(dir / "missing.json").string(), "--quick"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.out.find("missing.json"), std::string::npos) << r.out;
    r = tradeoff({test::kSeedScenePath, "--depths", "0,99"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.out.find("--depths"), std::string::npos) << r.out;
    r = tradeoff({test::kSeedScenePath, "--width", "0"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.out.find("--width"), std::string::npos) << r.out;
    r = tradeoff({test::kSeedScenePath, "--samples", "x"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.out.find("grid flag"), std::string::npos) << r.out;
    r = tradeoff({test::kSeedScenePath, "--no-such-flag"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(dir.entries().empty()) << test::joined(dir.entries());
}

}  // namespace
}  // namespace whitted
