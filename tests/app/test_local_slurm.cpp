// The single-node Slurm of scripts/local-slurm.sh,
// started and stopped around these tests by the CTest fixture local_slurm,
// runs what whitted-farm submits, and what a farm relies on: the regions of
// the seed as an array job and a merge job that depends on it give the local
// render, bit for bit; a failed task cancels the merge (kill_invalid_depend)
// and leaves the output path untouched.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "image/image_error.h"
#include "image/image_io.h"
#include "support/test_support.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;
using test::shellQuote;
using test::TempDir;

const std::string kRender = WHITTED_RENDER_EXE;

using test::ProgramRun;
using test::runShell;

// Submits a batch job running `script` (a shell command); its id.
std::string submit(const std::vector<std::string>& flags, const std::string& script) {
    const std::string command = test::commandLine(
        "sbatch", test::appended(test::appended({"--parsable"}, flags), {"--wrap", script}));
    const ProgramRun r = runShell(command);
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
        const ProgramRun r = runShell("squeue -h -t all -j " + job + " -o %T 2>/dev/null");
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
           shellQuote(test::kSeedScenePath) +
           " --width 64 --height 48 --spp 2 --quiet --region \"$region\" -o " +
           shellQuote((dir / "part").string()) + "\"$SLURM_ARRAY_TASK_ID\".exr";
}

std::string mergeTask(const TempDir& dir, int parts, const fs::path& out) {
    std::vector<std::string> args = {"merge"};
    for (int i = 0; i < parts; ++i)
        args.push_back((dir / ("part" + std::to_string(i) + ".exr")).string());
    args.insert(args.end(), {"-o", out.string(), "--quiet"});
    return "exec " + test::commandLine(kRender, args);
}

TEST(LocalSlurm, RegionsOfAnArrayJobMergeIntoTheLocalRender) {
    ASSERT_NE(std::getenv("SLURM_CONF"), nullptr) << "run through ctest: the fixture starts Slurm";
    TempDir dir;
    const fs::path local = dir / "local.exr", merged = dir / "merged.exr";
    ASSERT_EQ(std::system(
                  test::commandLine(kRender, {test::kSeedScenePath, "--width", "64", "--height",
                                              "48", "--spp", "2", "--quiet", "-o", local.string()})
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

// ---- whitted-farm ------------------------------------------------------------------

// whitted-farm with the arguments, its stdout and stderr together.
const test::Program farm{WHITTED_FARM_EXE, test::Stderr::Merged};

// The local render of the same command, for comparison.
void renderLocally(const std::vector<std::string>& args) {
    const std::string command = test::commandLine(kRender, args);
    ASSERT_EQ(std::system((command + " --quiet").c_str()), 0) << command;
}

const std::vector<std::string> kSmall = {"--width", "64", "--height", "48", "--spp", "2"};

// A scene and an output whose paths have spaces, quotes and $ in them.
TEST(WhittedFarm, TilesOnSlurmEqualTheLocalRender_PathsReachTheJobsIntact) {
    TempDir dir;
    const fs::path scene = dir / "my scene 'quoted' $HOME.json";
    fs::copy_file(test::kSeedScenePath, scene);
    const fs::path out = dir / "the $1 \"out\" image.png", local = dir / "local.png";
    const ProgramRun r = farm(
        test::appended({scene.string(), "-o", out.string(), "--tiles", "4", "--wait"}, kSmall));
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("4 of 4 regions to render"), std::string::npos) << r.out;
    renderLocally(test::appended({scene.string(), "-o", local.string()}, kSmall));
    EXPECT_TRUE(readImage(out).rgb == readImage(local).rgb);
    // The same command again: nothing to do.
    const ProgramRun again = farm(
        test::appended({scene.string(), "-o", out.string(), "--tiles", "4", "--wait"}, kSmall));
    EXPECT_EQ(again.exitCode, 0) << again.out;
    EXPECT_NE(again.out.find("already done"), std::string::npos) << again.out;
}

// A quality on the farm: planned once, in a job the tasks wait for, then
// each task renders its region to the plan, and the merged picture meets the
// target against a converged render. Flags that contradict are refused
// before anything is submitted.
TEST(WhittedFarm, TilesToAQualityOnSlurm_MeetTheTarget) {
    TempDir dir;
    const std::vector<std::string> size = {"--width", "64", "--height", "48"};
    const fs::path out = dir / "preview.exr", ref = dir / "ref.exr";
    const ProgramRun r = farm(test::appended({test::kSeedScenePath, "-o", out.string(), "--tiles",
                                              "4", "--quality", "preview", "--wait"},
                                             size));
    ASSERT_EQ(r.exitCode, 0) << r.out;
    // Planned once, in the plan job, and shown once it was made.
    const std::string said = "quality Preview: 35 dB, no pixel off by more than 64 codes\n  depth ";
    EXPECT_NE(r.out.find("whitted-farm: the plan, job "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(said), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find(said), r.out.rfind(said)) << r.out;
    const fs::path work = out.string() + ".farm", planFile = work / "plan.json";
    EXPECT_NE(test::readFile(work / "prepare.log").find(said), std::string::npos);
    ASSERT_TRUE(fs::exists(planFile));
    // Every task was given the plan, and started after it was written: their
    // logs (empty: the tasks are quiet) were made when they started.
    for (const char* task : {"task-0", "task-1", "task-2", "task-3"}) {
        EXPECT_NE(test::readFile(work / (std::string(task) + ".args"))
                      .find(std::string("--plan", 7) + planFile.string()),
                  std::string::npos)
            << task;
        EXPECT_GE(fs::last_write_time(work / (std::string(task) + ".log")),
                  fs::last_write_time(planFile))
            << task;
    }
    if (!test::kSanitized) {  // the numbers, which the Release stage checks
        renderLocally(test::appended({test::kSeedScenePath, "-o", ref.string(), "--spp", "1024",
                                      "--depth", "12", "--precision", "double"},
                                     size));
        const ErrorStats e = measureError(readImage(out), readImage(ref));
        EXPECT_GE(e.psnrSrgb8, 35.0);
        EXPECT_LE(e.largest, 64.0);
    }
    const ImageMetadata merged = readImagePart(out).metadata;
    EXPECT_EQ(merged.qualityTarget, "Preview: 35 dB, no pixel off by more than 64 codes");
    EXPECT_EQ(merged.qualityReached.rfind("4 regions, each rendered to it: depth ", 0), 0u)
        << merged.qualityReached;

    // Taken up again with a region missing: its plan is the one made before,
    // said once, and no job makes it again.
    const auto planned = fs::last_write_time(planFile);
    fs::remove(out);
    fs::remove(work / "part.1.exr");
    const ProgramRun again = farm(test::appended({test::kSeedScenePath, "-o", out.string(),
                                                  "--tiles", "4", "--quality", "preview", "--wait"},
                                                 size));
    ASSERT_EQ(again.exitCode, 0) << again.out;
    EXPECT_NE(again.out.find("1 of 4 regions to render"), std::string::npos) << again.out;
    EXPECT_EQ(again.out.find("the plan, job "), std::string::npos) << again.out;
    EXPECT_NE(again.out.find("the plan, made before, in " + planFile.string() + ":\n" + said),
              std::string::npos)
        << again.out;
    EXPECT_EQ(again.out.find(said), again.out.rfind(said)) << again.out;
    EXPECT_EQ(fs::last_write_time(planFile), planned);
    EXPECT_TRUE(fs::exists(out));

    const fs::path refused = dir / "refused.exr";
    const ProgramRun bad = farm(test::appended(
        {test::kSeedScenePath, "-o", refused.string(), "--tiles", "4", "--max-error", "8"}, size));
    EXPECT_EQ(bad.exitCode, 2) << bad.out;
    EXPECT_NE(bad.out.find("--max-error needs --target-psnr"), std::string::npos) << bad.out;
    EXPECT_FALSE(fs::exists(refused.string() + ".farm"));
}

// The plan job fails (a tracer kernel no CPU has: sbatch passes the
// environment on): its log is shown, and no task runs without a plan.
TEST(WhittedFarm, AFailedPlanJob_ShowsItsLogAndRunsNoTask) {
    TempDir dir;
    const fs::path out = dir / "never.png";
    const ProgramRun r = farm(test::appended({test::kSeedScenePath, "-o", out.string(), "--tiles",
                                              "2", "--quality", "draft", "--wait"},
                                             kSmall),
                              "WHITTED_KERNEL=no-such-kernel");
    EXPECT_EQ(r.exitCode, 1) << r.out;
    const fs::path work = out.string() + ".farm";
    EXPECT_NE(r.out.find("the plan job ("), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("its log, " + (work / "prepare.log").string() + ":\n"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("no tracer kernel is named \"no-such-kernel\""), std::string::npos)
        << r.out;
    for (const char* log : {"task-0.log", "task-1.log", "merge.log"})
        EXPECT_FALSE(fs::exists(work / log)) << log;
    EXPECT_FALSE(fs::exists(out));
}

TEST(WhittedFarm, TurntableFramesOnSlurmEqualTheLocalFrames) {
    TempDir dir;
    const ProgramRun r = farm(test::appended(
        {test::kSeedScenePath, "-o", (dir / "spin.png").string(), "--turntable", "3", "--wait"},
        kSmall));
    ASSERT_EQ(r.exitCode, 0) << r.out;
    renderLocally(test::appended(
        {test::kSeedScenePath, "-o", (dir / "local.png").string(), "--turntable", "3"}, kSmall));
    for (const char* n : {"0001", "0002", "0003"})
        EXPECT_TRUE(readImage(dir / (std::string("spin.") + n + ".png")).rgb ==
                    readImage(dir / (std::string("local.") + n + ".png")).rgb)
            << n;
}

// The id of the job of that name whose working directory is `work`, once it
// is queued (at most 20 s); empty if it never is.
std::string jobRunningIn(const std::string& name, const fs::path& work) {
    std::string suffix = " ";  // appended, not " " + ...: GCC 12 warns falsely (-Wrestrict)
    suffix.append(work.string()).append("\n");
    for (int i = 0; i < 200; ++i) {
        const ProgramRun q = runShell("squeue -h -n " + name + " -o '%F %Z' 2>/dev/null");
        for (std::size_t at = 0, end; (end = q.out.find('\n', at)) != std::string::npos;
             at = end + 1) {
            const std::string line = q.out.substr(at, end + 1 - at);
            if (line.size() > suffix.size() && line.ends_with(suffix))
                return line.substr(0, line.size() - suffix.size());
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return {};
}

// A task cancelled while its jobs are held: the farm fails naming it with its
// log, the output is not written; run again, it renders only that region.
TEST(WhittedFarm, ACancelledTaskFails_TheRerunRendersOnlyWhatIsMissing) {
    TempDir dir;
    const fs::path out = dir / "out.png", work = dir / "out.png.farm";
    const std::vector<std::string> args = test::appended(
        {test::kSeedScenePath, "-o", out.string(), "--tiles", "4", "--wait"}, kSmall);
    ProgramRun failed;
    std::thread first([&] { failed = farm(test::appended(args, {"--sbatch-arg=--hold"})); });
    // This farm's jobs, by their work directory: the other farm tests may be
    // running theirs at the same time under the same names.
    const std::string job = jobRunningIn("whitted-farm", work);
    const std::string merge = jobRunningIn("whitted-merge", work);
    if (job.empty() || merge.empty()) {  // cancel what did appear, so the farm returns
        runShell("scancel " + job + " " + merge);
        first.join();
        FAIL() << "the farm's held jobs never appeared:\n" << failed.out;
    }
    EXPECT_EQ(runShell("scancel " + job + "_2").exitCode, 0);
    // Both held jobs released: a held merge is not cancelled for its failed
    // dependency until it is.
    EXPECT_EQ(runShell("scontrol release " + job + "," + merge).exitCode, 0);
    first.join();
    EXPECT_EQ(failed.exitCode, 1) << failed.out;
    EXPECT_NE(failed.out.find("task 2 (job " + job + "_2)"), std::string::npos) << failed.out;
    EXPECT_NE(failed.out.find("task-2.log"), std::string::npos) << failed.out;
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(work / "part.2.exr"));

    const auto kept = fs::last_write_time(work / "part.0.exr");
    const ProgramRun second = farm(args);
    ASSERT_EQ(second.exitCode, 0) << second.out;
    EXPECT_NE(second.out.find("1 of 4 regions to render"), std::string::npos) << second.out;
    EXPECT_EQ(fs::last_write_time(work / "part.0.exr"), kept) << "a finished region rendered again";
    renderLocally(
        test::appended({test::kSeedScenePath, "-o", (dir / "local.png").string()}, kSmall));
    EXPECT_TRUE(readImage(out).rgb == readImage(dir / "local.png").rgb);
}

}  // namespace
}  // namespace whitted
