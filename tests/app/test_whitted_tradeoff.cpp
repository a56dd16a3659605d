// End-to-end tests of whitted-tradeoff: a --quick run on a small seed writes
// every file with the expected rows, the report mode chooses presets from it,
// and bad input exits 2 with a message naming the file or flag.
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scene/scene_io.h"
#include "support/test_support.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

std::string quote(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

struct ProgramRun {
    int exitCode = -1;
    std::string output;  // stdout and stderr
};

ProgramRun tradeoff(const TempDir& dir, const std::vector<std::string>& args) {
    const fs::path log = dir.path().parent_path() / (dir.path().filename().string() + ".log");
    std::string cmd = quote(WHITTED_TRADEOFF_EXE);
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on " " + std::string.
    for (const std::string& a : args) cmd.append(" ").append(quote(a));
    cmd.append(" >").append(quote(log.string())).append(" 2>&1");
    const int status = std::system(cmd.c_str());
    ProgramRun r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, test::readFile(log)};
    fs::remove(log);
    return r;
}

std::vector<std::string> lines(const fs::path& file) {
    std::ifstream in(file);
    std::vector<std::string> out;
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

TEST(WhittedTradeoff, QuickRun_WritesEveryFileWithOneRowPerPoint) {
    TempDir dir;
    Scene seed = loadScene(WHITTED_SCENES_DIR "/seed.json");
    seed.render.width = 64;
    seed.render.height = 48;
    saveScene(seed, dir / "small.json");
    const fs::path out = dir / "out";
    const ProgramRun r =
        tradeoff(dir, {(dir / "small.json").string(), "--out-dir", out.string(), "--quick"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
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
        tradeoff(dir, {"--report", (dir / "tradeoff.md").string(), "--dirs", out.string()});
    ASSERT_EQ(rep.exitCode, 0) << rep.output;
    const std::string md = test::readFile(dir / "tradeoff.md");
    EXPECT_NE(md.find("| Draft |"), std::string::npos);
    EXPECT_NE(md.find("| Final |"), std::string::npos);
    EXPECT_NE(md.find("## small"), std::string::npos);  // the scene file's name
    EXPECT_NE(md.find("(out/plot.png)"), std::string::npos);
    EXPECT_NE(rep.output.find("Draft: "), std::string::npos) << rep.output;
}

TEST(WhittedTradeoff, WidthAndHeight_OverrideTheScenesSize) {
    TempDir dir;
    const fs::path out = dir / "out";
    const ProgramRun r =
        tradeoff(dir, {WHITTED_SCENES_DIR "/seed.json", "--out-dir", out.string(), "--width", "40",
                       "--height", "30", "--samples", "1", "--depths", "1", "--precisions", "float",
                       "--scales", "1", "--reference-spp", "4", "--progressive-spp", "1"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::vector<std::string> csv = lines(out / "points.csv");
    ASSERT_EQ(csv.size(), 2u);
    EXPECT_EQ(csv[1].rfind("1,1,float,1,40,30,", 0), 0u) << csv[1];
}

TEST(WhittedTradeoff, BadInput_ExitsTwoNamingTheProblem) {
    TempDir dir;
    ProgramRun r = tradeoff(dir, {(dir / "missing.json").string(), "--quick"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("missing.json"), std::string::npos) << r.output;
    r = tradeoff(dir, {WHITTED_SCENES_DIR "/seed.json", "--depths", "0,99"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("--depths"), std::string::npos) << r.output;
    r = tradeoff(dir, {WHITTED_SCENES_DIR "/seed.json", "--width", "0"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("--width"), std::string::npos) << r.output;
    r = tradeoff(dir, {WHITTED_SCENES_DIR "/seed.json", "--samples", "x"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("grid flag"), std::string::npos) << r.output;
    r = tradeoff(dir, {WHITTED_SCENES_DIR "/seed.json", "--no-such-flag"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(dir.entries().empty()) << test::joined(dir.entries());
}

}  // namespace
}  // namespace whitted
