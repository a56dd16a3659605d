// End-to-end tests of the whitted-numerics sweep program on a tiny image and its
// --quick sweep: exit codes, the report, the CSV and the pictures it links.
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "support/test_support.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;
using test::ProgramRun;
using test::TempDir;

// whitted-numerics with the arguments, its stdout and stderr together in `out`.
const test::Program runNumerics{WHITTED_NUMERICS_EXE, test::Stderr::Merged};

// Fields of one CSV line; a quoted field (the offset "(1e2, 1e2, 1e2)") may hold commas.
std::vector<std::string> splitCsvLine(const std::string& line) {
    std::vector<std::string> fields;
    std::string field;
    bool quoted = false;
    for (char c : line) {
        if (c == '"')
            quoted = !quoted;
        else if (c == ',' && !quoted)
            fields.push_back(std::exchange(field, {}));
        else
            field += c;
    }
    fields.push_back(field);
    return fields;
}

// The lines of the report's point tables that start "| k | transform |", k signed
// as the report writes it ("+2", "0", "-3").
std::vector<std::string> tableRows(const std::string& md, int k, const std::string& transform) {
    std::string start = "| ";
    start.append(k > 0 ? "+" : "").append(std::to_string(k)).append(" | ").append(transform);
    start.append(" |");
    std::vector<std::string> rows;
    std::istringstream lines(md);
    for (std::string line; std::getline(lines, line);)
        if (line.starts_with(start)) rows.push_back(line);
    return rows;
}

class QuickSweep : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        dir_ = new TempDir;
        run_ = runNumerics({"--scene", test::kSeedScenePath, "--out-dir", dir_->path().string(),
                            "--width", "24", "--height", "18", "--threads", "2", "--quick"});
    }
    static void TearDownTestSuite() {
        delete dir_;
        dir_ = nullptr;
    }
    static TempDir* dir_;
    static ProgramRun run_;
};
TempDir* QuickSweep::dir_ = nullptr;
ProgramRun QuickSweep::run_;

TEST_F(QuickSweep, ExitsZeroAndWritesReportCsvAndReference) {
    ASSERT_EQ(run_.exitCode, 0) << run_.out;
    EXPECT_TRUE(fs::is_regular_file(*dir_ / "numerics.md"));
    EXPECT_TRUE(fs::is_regular_file(*dir_ / "numerics.csv"));
    EXPECT_TRUE(fs::is_regular_file(*dir_ / "images/numerics/reference.png"));
    EXPECT_NE(run_.out.find("numerics.md"), std::string::npos) << run_.out;
}

TEST_F(QuickSweep, CsvHasOneRowPerQuickPoint_AndPowersOfTwoAreBitIdentical) {
    ASSERT_EQ(run_.exitCode, 0) << run_.out;
    std::istringstream csv(test::readFile(*dir_ / "numerics.csv"));
    std::string line;
    ASSERT_TRUE(std::getline(csv, line));
    const std::vector<std::string> header = splitCsvLine(line);
    ASSERT_GE(header.size(), 15u) << line;
    EXPECT_EQ(header[0], "sweep");
    EXPECT_EQ(header[11], "bit_identical");
    std::map<std::tuple<std::string, std::string, int>, int> seen;
    while (std::getline(csv, line)) {
        const std::vector<std::string> f = splitCsvLine(line);
        ASSERT_EQ(f.size(), header.size()) << line;
        ++seen[{f[0], f[1], std::stoi(f[2])}];
        if (f[0] == "scale2")
            EXPECT_EQ(f[11], "yes") << "2^k must not change the image: " << line;
        else
            EXPECT_EQ(f[11], "") << line;
        EXPECT_EQ(f[14], "") << "refused: " << line;
    }
    std::map<std::tuple<std::string, std::string, int>, int> expected;
    for (const char* p : {"float", "double"}) {
        for (int k = -2; k <= 2; ++k) expected[{"scale10", p, k}] = 1;
        for (int k = -3; k <= 3; ++k) expected[{"scale2", p, k}] = 1;
        for (int k = 0; k <= 2; ++k) expected[{"translate", p, k}] = 1;
    }
    EXPECT_EQ(seen, expected);
}

TEST_F(QuickSweep, ReportHasRangeTableAndEveryPointRow) {
    ASSERT_EQ(run_.exitCode, 0) << run_.out;
    const std::string md = test::readFile(*dir_ / "numerics.md");
    EXPECT_NE(md.find("Generated"), std::string::npos);
    EXPECT_NE(md.find("--quick"), std::string::npos) << "the header names the command";
    // The seed's one sample, in words a reader reads (not "1 sample(s)").
    EXPECT_NE(md.find("at 24×18, max depth 2, 1 sample per pixel, 2 threads"), std::string::npos)
        << md.substr(0, 600);
    EXPECT_NE(md.find("## Measured ranges"), std::string::npos);
    EXPECT_NE(md.find("## Every point"), std::string::npos);
    // One row per precision for each point; 2^k rows say bit-identical and hold.
    for (int k = -2; k <= 2; ++k)
        EXPECT_EQ(tableRows(md, k, "1e" + std::to_string(k)).size(), 2u) << "10^" << k;
    for (int k = -3; k <= 3; ++k) {
        const auto rows = tableRows(md, k, "2^" + std::to_string(k));
        EXPECT_EQ(rows.size(), 2u) << "2^" << k;
        for (const std::string& row : rows) {
            EXPECT_NE(row.find("| yes |"), std::string::npos) << row;
            EXPECT_NE(row.find("| holds |"), std::string::npos) << row;
        }
    }
    for (int k = 0; k <= 2; ++k) {
        const std::string t = "1e" + std::to_string(k);
        std::string offset = "(";
        offset.append(t).append(", ").append(t).append(", ").append(t).append(")");
        EXPECT_EQ(tableRows(md, k, offset).size(), 2u) << offset;
    }
}

TEST_F(QuickSweep, EveryLinkedPictureExists) {
    ASSERT_EQ(run_.exitCode, 0) << run_.out;
    const std::string md = test::readFile(*dir_ / "numerics.md");
    // Markdown links "](images/numerics/....png)". Not <regex>: GCC 12 warns
    // inside it (-Wmaybe-uninitialized) in the sanitizer builds.
    const std::string opening = "](images/numerics/";
    int links = 0;
    for (std::size_t at = md.find(opening); at != std::string::npos;
         at = md.find(opening, at + 1)) {
        const std::size_t begin = at + 2, end = md.find(')', begin);
        ASSERT_NE(end, std::string::npos) << md.substr(at, 80);
        const std::string target = md.substr(begin, end - begin);
        if (!target.ends_with(".png")) continue;
        EXPECT_TRUE(fs::is_regular_file(*dir_ / target)) << target;
        ++links;
    }
    EXPECT_GE(links, 1);
}

TEST(WhittedNumerics, BadFlag_ExitsTwo) {
    TempDir dir;
    const ProgramRun r = runNumerics({"--width", "0", "--out-dir", dir.path().string()});
    EXPECT_EQ(r.exitCode, 2) << r.out;
    EXPECT_NE(r.out.find("--width"), std::string::npos) << r.out;
    EXPECT_TRUE(dir.entries().empty()) << test::joined(dir.entries());
}

TEST(WhittedNumerics, MissingScene_ExitsTwo) {
    TempDir dir;
    const ProgramRun r =
        runNumerics({"--scene", (dir / "none.json").string(), "--out-dir", dir.path().string()});
    EXPECT_EQ(r.exitCode, 2) << r.out;
    EXPECT_NE(r.out.find("none.json"), std::string::npos) << r.out;
    EXPECT_TRUE(dir.entries().empty()) << test::joined(dir.entries());
}

}  // namespace
}  // namespace whitted
