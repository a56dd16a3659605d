// Issue 14, item 4 (its first part): the single-node Slurm of
// scripts/local-slurm.sh, started and stopped around these tests by the CTest
// fixture local_slurm, runs what a farm submits. The regions of the seed as
// an array job and a merge job that depends on it give the local render, bit
// for bit; a failed task cancels the merge (kill_invalid_depend) and leaves
// the output path untouched. whitted-farm (item 3) will submit these jobs.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include <sys/wait.h>

#include <gtest/gtest.h>

#include "image_io.h"
#include "test_support.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;
using test::shellQuote;
using test::TempDir;

const std::string kSeed = std::string(WHITTED_SCENES_DIR) + "/seed.json";
const std::string kRender = WHITTED_RENDER_EXE;

struct Shell {
    int exitCode = -1;
    std::string out;
};

Shell shell(const std::string& command) {
    Shell r;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return r;
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
        r.out.append(buffer, n);
    const int status = pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

// Submits a batch job running `script` (a shell command); its id.
std::string submit(const std::vector<std::string>& flags, const std::string& script) {
    std::string command = "sbatch --parsable";
    for (const std::string& f : flags) command.append(" ").append(shellQuote(f));
    command.append(" --wrap ").append(shellQuote(script));
    const Shell r = shell(command);
    EXPECT_EQ(r.exitCode, 0) << command << "\n" << r.out;
    std::string id = r.out;
    while (!id.empty() && (id.back() == '\n' || id.back() == ' ')) id.pop_back();
    return id;
}

// The states of the job's tasks ("COMPLETED", "FAILED", ...), once none of
// them is pending or running (at most a minute).
std::vector<std::string> finalStates(const std::string& job) {
    if (job.empty()) return {};  // not submitted (which submit() reported)
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    for (;;) {
        const Shell r = shell("squeue -h -t all -j " + job + " -o %T 2>/dev/null");
        std::vector<std::string> states;
        std::size_t at = 0;
        for (std::size_t end; (end = r.out.find('\n', at)) != std::string::npos; at = end + 1)
            states.push_back(r.out.substr(at, end - at));
        bool finished = !states.empty();
        for (const std::string& s : states)
            finished = finished && s != "PENDING" && s != "RUNNING" && s != "CONFIGURING" &&
                       s != "COMPLETING";
        if (finished || std::chrono::steady_clock::now() > deadline) return states;
        std::this_thread::sleep_for(std::chrono::milliseconds(250));
    }
}

// The task's command: render region number $SLURM_ARRAY_TASK_ID of the list.
std::string regionTask(const TempDir& dir, const std::vector<std::string>& regions) {
    std::string cases;
    for (std::size_t i = 0; i < regions.size(); ++i)
        cases.append(std::to_string(i)).append(") region=").append(regions[i]).append(" ;; ");
    return "case $SLURM_ARRAY_TASK_ID in " + cases + "esac; exec " + shellQuote(kRender) + " " +
           shellQuote(kSeed) + " --width 64 --height 48 --spp 2 --quiet --region \"$region\" -o " +
           shellQuote((dir / "part").string()) + "\"$SLURM_ARRAY_TASK_ID\".exr";
}

std::string mergeTask(const TempDir& dir, int parts, const fs::path& out) {
    std::string command = "exec " + shellQuote(kRender) + " merge";
    for (int i = 0; i < parts; ++i)
        command.append(" ").append(
            shellQuote((dir / ("part" + std::to_string(i) + ".exr")).string()));
    return command + " -o " + shellQuote(out.string()) + " --quiet";
}

TEST(LocalSlurm, RegionsOfAnArrayJobMergeIntoTheLocalRender) {
    ASSERT_NE(std::getenv("SLURM_CONF"), nullptr) << "run through ctest: the fixture starts Slurm";
    TempDir dir;
    const fs::path local = dir / "local.exr", merged = dir / "merged.exr";
    ASSERT_EQ(
        std::system((shellQuote(kRender) + " " + shellQuote(kSeed) +
                     " --width 64 --height 48 --spp 2 --quiet -o " + shellQuote(local.string()))
                        .c_str()),
        0);
    const std::vector<std::string> regions = {"0,0,32,24", "32,0,64,24", "0,24,32,48",
                                              "32,24,64,48"};
    const std::string tasks = submit({"--array=0-3", "--output=" + (dir / "task-%a.log").string()},
                                     regionTask(dir, regions));
    const std::string merge =
        submit({"--dependency=afterok:" + tasks, "--output=" + (dir / "merge.log").string()},
               mergeTask(dir, 4, merged));
    const std::vector<std::string> states = finalStates(tasks);
    EXPECT_EQ(test::joined(states), "[COMPLETED, COMPLETED, COMPLETED, COMPLETED]");
    ASSERT_EQ(test::joined(finalStates(merge)), "[COMPLETED]") << test::readFile(dir / "merge.log");
    const Image a = readImage(local), b = readImage(merged);
    EXPECT_EQ(a.width, b.width);
    EXPECT_TRUE(a.rgb == b.rgb) << "the merged regions differ from the local render";
}

TEST(LocalSlurm, AFailedTaskCancelsTheMergeAndLeavesTheOutputAlone) {
    ASSERT_NE(std::getenv("SLURM_CONF"), nullptr) << "run through ctest: the fixture starts Slurm";
    TempDir dir;
    const fs::path merged = dir / "merged.exr";
    test::writeFile(merged, "the user's earlier image");
    // Task 1's region lies outside the 64x48 image: whitted-render exits 2.
    const std::string tasks = submit({"--array=0-1", "--output=" + (dir / "task-%a.log").string()},
                                     regionTask(dir, {"0,0,64,24", "0,24,64,99"}));
    const std::string merge =
        submit({"--dependency=afterok:" + tasks, "--output=" + (dir / "merge.log").string()},
               mergeTask(dir, 2, merged));
    EXPECT_EQ(test::joined(finalStates(tasks)), "[COMPLETED, FAILED]");
    EXPECT_EQ(test::joined(finalStates(merge)), "[CANCELLED]");
    EXPECT_NE(test::readFile(dir / "task-1.log").find("--region 0,24,64,99"), std::string::npos)
        << test::readFile(dir / "task-1.log");
    EXPECT_EQ(test::readFile(merged), "the user's earlier image");
}

}  // namespace
}  // namespace whitted
