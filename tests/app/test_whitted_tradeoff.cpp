// End-to-end tests of whitted-tradeoff: a --quick run on a small seed writes
// every file with the expected rows, the report mode chooses presets from it,
// and bad input exits 2 with a message naming the file or flag.
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "analysis/quality_table.h"
#include "image/image_io.h"
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

// A --quick run on a 64x48 seed saved in `dir`, into `dir`/out.
ProgramRun quickRun(const TempDir& dir) {
    saveScene(test::seedScene(64, 48), dir / "small.json");
    return tradeoff({(dir / "small.json").string(), "--out-dir", (dir / "out").string(), "--quick"});
}

TEST(WhittedTradeoff, QuickRun_WritesEveryFileWithOneRowPerPoint) {
    TempDir dir;
    const fs::path out = dir / "out";
    const ProgramRun r = quickRun(dir);
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

// bench_quality's rows (quality_table.h) become the report's section on
// rendering to a quality: each row's target, what the plan chose, what was
// measured beside the fixed preset, and the tally; a scene's name may hold a
// comma. A malformed row is bad
// input: the file and line named, and the report left as it was.
TEST(WhittedTradeoff, ReportWithQualityCsv_TargetsAgainstWhatWasMeasured) {
    TempDir dir;
    const fs::path out = dir / "out";
    ASSERT_EQ(quickRun(dir).exitCode, 0);
    // clang-format off
    const QualityRow draft{"2026-12-05", "glass", 640, 480, "Draft", 20.0, std::nullopt, 2,
                           false, 1.0, 21.34, 163.0, true, 21.3, 163.0, true, 1.02,
                           "the preset", 1.02};
    const QualityRow final{"2026-12-05", "generated: 300 balls, seed 7", 640, 480, "Final", 50.0,
                           16.0, 36, false, 80.53, 55.04, 12.4, true, 52.1, 20.0, false, 0.61,
                           "256 spp", 0.2};
    const QualityRow preview{"2026-12-05", "field", 640, 480, "Preview", 35.0, 64.0, 21, true,
                             13.7, 46.1, 58.0, true, 36.8, 133.0, false, 3.12, "", std::nullopt};
    // clang-format on
    const fs::path csv = dir / "quality.csv";
    std::ofstream(csv) << qualityCsvHeader() << "\n"
                       << qualityCsvLine(draft) << "\n"
                       << qualityCsvLine(final) << "\n"
                       << qualityCsvLine(preview) << "\n";
    const fs::path md = dir / "tradeoff.md";
    const std::vector<std::string> report{"--report",   md.string(),     "--dirs",
                                          out.string(), "--quality-csv", csv.string()};
    const ProgramRun r = tradeoff(report);
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const std::string text = test::readFile(md);
    EXPECT_NE(text.find("## Rendering to a quality"), std::string::npos);
    EXPECT_NE(text.find("Measured on 2026-12-05 at 640x480"), std::string::npos);
    EXPECT_NE(text.find("| glass | Draft: 20 dB | 2, 1.0 | 21.3 dB, 163 codes, met | "
                        "21.3 dB, 163 codes, met | 1.02 (the preset) |"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("| generated: 300 balls, seed 7 | Final: 50 dB, ≤ 16 codes | 36, 80.5 | "
                        "55.0 dB, 12 codes, met "
                        "| 52.1 dB, 20 codes, **missed** | 0.20 (256 spp) |"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("| field | Preview: 35 dB, ≤ 64 codes | 21*, 13.7 | 46.1 dB, 58 codes, "
                        "met | 36.8 dB, 133 codes, **missed** | none up to 256 spp meets it |"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("Rendered to the target, 3 of 3 met it"), std::string::npos);
    EXPECT_NE(text.find("The fixed presets met 1 of 3."), std::string::npos);

    std::ofstream(csv, std::ios::app) << "2026-12-05,glass,640,480,Final,50,16,deep\n";
    ProgramRun bad = tradeoff(report);
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.out.find("quality.csv: line 5: expected 19 columns"), std::string::npos)
        << bad.out;
    std::ofstream(csv, std::ios::trunc) << qualityCsvHeader() << "\n"
                                        << "2026-12-05,glass,640,480,Final,50,16,deep,no,80,55,"
                                           "12,yes,52,20,no,0.6,,\n";
    bad = tradeoff(report);
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.out.find("quality.csv: line 2: malformed value"), std::string::npos) << bad.out;
    EXPECT_EQ(test::readFile(md), text);
}

TEST(WhittedTradeoff, ReportWithSamplerCsv_ComparesWhitted1980WithTheFastestOfOursAsGood) {
    TempDir dir;
    const fs::path out = dir / "out";
    ASSERT_EQ(quickRun(dir).exitCode, 0);
    const fs::path csv = dir / "whitted1980.csv";
    std::ofstream(csv) << "scene,sampler,setting,width,height,camera_rays_per_pixel,"
                          "rays_per_pixel,seconds,psnr_db,largest_codes\n"
                       << "seed,fixed,1 spp,160,120,1,3.1,0.002,31.5,120\n"
                       << "seed,fixed,4 spp,160,120,4,12.3,0.008,38.2,60\n"
                       << "seed,adaptive,to 40 dB,160,120,2.5,8,0.006,40.5,50\n"
                       << "seed,whitted1980,\"threshold 8, 2 cuts\",160,120,1.4,4.4,0.003,36.0,90\n"
                       << "seed,whitted1980,\"threshold 1, 4 cuts\",160,120,9,28,0.02,45.0,30\n";
    const fs::path md = dir / "tradeoff.md";
    const ProgramRun r =
        tradeoff({"--report", md.string(), "--dirs", out.string(), "--sampler-csv", csv.string()});
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const std::string text = test::readFile(md);
    EXPECT_NE(text.find("## Whitted's 1980 sampling against ours"), std::string::npos) << text;
    // 36 dB in 3 ms: the fastest of ours as good is the adaptive 40.5 dB in 6 ms,
    // not 4 spp's 38.2 dB in 8 ms.
    EXPECT_NE(text.find("| threshold 8, 2 cuts | 1.40 | 3.0 | 36.0 | 90 | adaptive to 40 dB "
                        "(40.5 dB) | 6.0 | **0.50** |"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("| threshold 1, 4 cuts | 9.00 | 20.0 | 45.0 | 30 | none of ours reaches "
                        "it | | |"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("In all, 1 of 2 settings"), std::string::npos) << text;
    EXPECT_NE(text.find("![seed: error against time](tradeoff/whitted1980/seed.png) "
                        "![seed: error against camera rays](tradeoff/whitted1980/seed-rays.png)"),
              std::string::npos)
        << text;
    for (const char* plot : {"seed.png", "seed-rays.png"}) {
        const Image image = readImage(dir / "tradeoff/whitted1980" / plot);
        EXPECT_EQ(image.width, 560) << plot;
        EXPECT_EQ(image.height, 400) << plot;
    }

    std::ofstream(csv, std::ios::app) << "seed,fixed,16 spp,160,120,16,fast\n";
    const ProgramRun bad =
        tradeoff({"--report", md.string(), "--dirs", out.string(), "--sampler-csv", csv.string()});
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.out.find("whitted1980.csv: line 7"), std::string::npos) << bad.out;
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
