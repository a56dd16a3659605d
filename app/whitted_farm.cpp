// whitted-farm: renders a scene on a Slurm cluster. The image's
// regions (--tiles N) or a turntable's frames (--turntable N) become an array
// job of whitted-render commands, and the regions a merge job that depends on
// it (afterok); --wait follows them to the end. With a quality (--quality,
// --target-psnr), the whole picture is planned here, once, and each task
// reads the plan (--plan) and samples its own region until that region meets
// the target. Re-running the same command renders only what is missing. No
// scheduler of our own: sbatch, squeue and scancel do it (app/farm/slurm.h).
// Exit codes: 0 submitted (or, with --wait, rendered); 2 bad input; 1 a job
// failed or Slurm refused; 130 interrupted (the jobs are cancelled).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <numeric>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

#include <CLI/CLI.hpp>

#include "cli_input.h"
#include "cli_main.h"
#include "farm/plan.h"
#include "farm/slurm.h"
#include "plan_file.h"
#include "render_flags.h"
#include "render_quality.h"
#include "scene/scene.h"
#include "scene/scene_io.h"

namespace fs = std::filesystem;
using namespace whitted;
using namespace whitted::farm;

namespace {

struct Options {
    std::string scene, output, workDir;
    int tiles = 0, turntable = 0, maxRunning = 0;
    RenderFlags render;    // passed on to every task
    QualityFlags quality;  // likewise: each task renders its part to the target
    std::vector<std::string> sbatchArgs;
    bool wait = false, quiet = false;
};

std::atomic<bool> interrupted{false};

extern "C" void onSignal(int) {
    interrupted = true;
}

// whitted-render beside this program: the same path must work on every node.
std::string renderProgram() {
    return (fs::read_symlink("/proc/self/exe").parent_path() / "whitted-render").string();
}

// Whether the plan file left in the work directory is this render's: one an
// older whitted-farm wrote, or a broken one, is made again by the plan job.
bool usablePlan(const fs::path& planFile, const Scene& scene, const QualityTarget& target) {
    try {
        readPlanFile(planFile, scene, target);
        return true;
    } catch (const std::runtime_error&) {
        return false;
    }
}

// The job that makes the plan every region's task renders to, before them:
// whitted-render without --output only plans (its log shows the plan).
Task planTask(const RenderCommand& command, const fs::path& planFile) {
    std::vector<std::string> argv = {command.program, command.scene};
    argv.insert(argv.end(), command.overrides.begin(), command.overrides.end());
    return {argv, planFile};
}

// `planFile`, if not empty: the plan every task of a render to a quality reads.
RenderCommand renderCommand(const Options& o, const fs::path& planFile) {
    std::vector<std::string> overrides = renderFlagArguments(o.render);
    for (std::string& flag : qualityFlagArguments(o.quality)) overrides.push_back(std::move(flag));
    if (!planFile.empty()) overrides.insert(overrides.end(), {"--plan", planFile.string()});
    return {renderProgram(), fs::absolute(o.scene).string(), std::move(overrides)};
}

// What the tasks of this command are, with the scene file's size and time:
// a work directory left by another command, or by another version of the
// scene, holds parts that must not be reused.
std::string fingerprint(const Plan& plan, const std::string& scene) {
    std::ostringstream s;
    for (const Task& t : plan.tasks)
        for (const std::string& a : t.argv) s << a << '\0';
    s << fs::file_size(scene) << '\0' << fs::last_write_time(scene).time_since_epoch().count();
    return s.str();
}

// Forgets the finished tasks of another command, whose parts or frames
// must be rendered again, and remembers this one's. True when it did.
bool startOverIfChanged(const Plan& plan, const fs::path& work, const std::string& print) {
    const fs::path file = work / "command";
    std::ifstream in(file, std::ios::binary);
    const std::string before((std::istreambuf_iterator<char>(in)), {});
    if (before == print) return false;
    for (const Task& t : plan.tasks) fs::remove(t.output);
    fs::create_directories(work);
    std::ofstream(file, std::ios::binary | std::ios::trunc) << print;
    return true;
}

// Whether every one of these tasks has written its file.
bool filesWritten(const Plan& plan, const std::vector<int>& tasks) {
    return std::all_of(tasks.begin(), tasks.end(),
                       [&](int i) { return fs::exists(plan.tasks[i].output); });
}

std::string readLog(const fs::path& file);

// Says which task failed and shows its log: the first task whose state is a
// failure, or, when squeue no longer shows it (a task cancelled before it
// ran), the first whose file is missing.
void reportFailedTask(const Jobs& jobs, const Plan& plan,
                      const std::map<std::string, std::string>& states, const fs::path& work) {
    std::optional<int> failed;
    std::string state = "did not finish";
    for (int i : jobs.indices) {
        const auto s = states.find(jobs.tasks + "_" + std::to_string(i));
        if (s != states.end() && failedState(s->second)) {
            failed = i;
            state = s->second;
            break;
        }
        if (!failed && !fs::exists(plan.tasks[i].output)) failed = i;
    }
    if (!failed) return;
    const std::string task = std::to_string(*failed);
    const fs::path log = work / ("task-" + task + ".log");
    std::cerr << "\nwhitted-farm: task " << task << " (job " << jobs.tasks << "_" << task << ") "
              << state << "; its log, " << log.string() << ":\n"
              << readLog(log);
}

std::string readLog(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    return text.empty() ? "(empty: the task never ran)\n" : text;
}

using JobStates = std::map<std::string, std::string>;

// The plan job, while it is in the queue: its failure said and the jobs
// cancelled (exit 1), else once it is done what it chose (sayPlan), once.
std::optional<int> followPlanJob(const Jobs& jobs, const JobStates& states, const fs::path& work,
                                 bool quiet, const std::function<void()>& sayPlan, bool& planSaid) {
    const auto p = states.find(jobs.prepare);
    if (p == states.end()) return std::nullopt;
    if (failedState(p->second)) {
        std::cerr << "\nwhitted-farm: the plan job (" << jobs.prepare << ") " << p->second
                  << "; its log, " << (work / "prepare.log").string() << ":\n"
                  << readLog(work / "prepare.log");
        cancelJobs(jobs);
        return kExitFailure;
    }
    if (p->second == "COMPLETED" && !planSaid) {
        if (!quiet) {
            std::fputc('\n', stderr);
            sayPlan();
        }
        planSaid = true;
    }
    return std::nullopt;
}

// The tasks done so far; a failed one said and the jobs cancelled (nothing).
std::optional<int> tasksDone(const Jobs& jobs, const Plan& plan, const JobStates& states,
                             const fs::path& work) {
    int done = 0;
    for (const auto& [id, state] : states) {
        const std::size_t underscore = id.find('_');
        if (underscore == std::string::npos || id.find('[') != std::string::npos) continue;
        if (state == "COMPLETED") ++done;
        if (!failedState(state)) continue;
        reportFailedTask(jobs, plan, states, work);
        cancelJobs(jobs);
        return std::nullopt;
    }
    return done;
}

// Once every job has ended: whether every file is there, said; the exit code.
int finished(const Jobs& jobs, const Plan& plan, const JobStates& states, const fs::path& work,
             const fs::path& output, bool quiet) {
    if (!quiet) std::fputc('\n', stderr);
    const auto merge = states.find(jobs.merge);
    if (!jobs.merge.empty() && merge->second != "COMPLETED") {
        if (filesWritten(plan, jobs.indices))
            std::cerr << "whitted-farm: the merge " << merge->second << "; its log:\n"
                      << readLog(work / "merge.log");
        else
            reportFailedTask(jobs, plan, states, work);
        return kExitFailure;
    }
    std::vector<int> all(plan.tasks.size());
    std::iota(all.begin(), all.end(), 0);
    if (!filesWritten(plan, all) || (plan.merge && !fs::exists(output))) {
        std::cerr << "whitted-farm: the jobs ended, but not every file is there\n";
        return kExitFailure;
    }
    if (!quiet)
        std::cerr << "whitted-farm: wrote "
                  << (plan.merge ? output.string()
                                 : plan.tasks.front().output.string() + " to " +
                                       plan.tasks.back().output.string())
                  << "\n";
    return kExitOk;
}

// Follows the jobs until the render is done (0) or a task fails (1), or the
// user interrupts (130: the jobs are cancelled).
int follow(const Jobs& jobs, const Plan& plan, const fs::path& work, const fs::path& output,
           bool quiet, const std::function<void()>& sayPlan) {
    const int total = static_cast<int>(jobs.indices.size());
    bool planSaid = jobs.prepare.empty();
    int shown = -1;
    for (;;) {
        if (interrupted) {
            cancelJobs(jobs);
            std::cerr << "\nwhitted-farm: interrupted; jobs cancelled\n";
            return kExitInterrupted;
        }
        const JobStates states = jobStates(jobs);
        if (const auto code = followPlanJob(jobs, states, work, quiet, sayPlan, planSaid))
            return *code;
        const std::optional<int> done = tasksDone(jobs, plan, states, work);
        if (!done) return kExitFailure;
        if (!quiet && *done != shown) {
            std::fprintf(stderr, "\rwhitted-farm: tasks done %d/%d", *done, total);
            std::fflush(stderr);
            shown = *done;
        }
        const auto merge = states.find(jobs.merge);
        const bool tasksGone = !jobs.tasks.empty() && states.empty();
        if (jobs.merge.empty() ? *done == total || tasksGone
                               : merge != states.end() && finishedState(merge->second))
            return finished(jobs, plan, states, work, output, quiet);
        std::this_thread::sleep_for(std::chrono::milliseconds(500));
    }
}

// What went to the queue, on stderr.
void sayQueued(const Jobs& jobs, const Plan& plan, bool turntable) {
    std::cerr << "whitted-farm: "
              << (jobs.prepare.empty() ? "" : "the plan, job " + jobs.prepare + "; ")
              << jobs.indices.size() << " of " << plan.tasks.size()
              << (turntable ? " frames" : " regions") << " to render"
              << (jobs.tasks.empty() ? "" : ", job " + jobs.tasks)
              << (jobs.merge.empty() ? "" : "; merge, job " + jobs.merge) << "\n";
}

// Flags that contradict each other or the picture: said, and exit 2. Refused
// here, not by every task. `target`: the quality the flags ask for, if any.
std::optional<int> checkFlags(const Options& o, int width, int height,
                              std::optional<QualityTarget>& target) {
    try {
        target = qualityTargetOf(o.quality);
    } catch (const std::invalid_argument& e) {
        std::cerr << "whitted-farm: " << e.what() << "\n";
        return kExitBadInput;
    }
    if (o.tiles > width * height) {
        std::cerr << "whitted-farm: --tiles " << o.tiles << ": more than the image's pixels\n";
        return kExitBadInput;
    }
    return std::nullopt;
}

int run(const Options& o) {
    if (!outputFormatOrSay("whitted-farm", o.output)) return kExitBadInput;
    std::optional<Scene> loaded = sceneOrSay("whitted-farm", o.scene);
    if (!loaded) return kExitBadInput;
    Scene& scene = *loaded;
    applyRenderFlags(o.render, scene.render);
    const int width = scene.render.width, height = scene.render.height;
    std::optional<QualityTarget> target;
    if (const auto code = checkFlags(o, width, height, target)) return *code;
    const fs::path output = fs::absolute(o.output);
    const fs::path work =
        o.workDir.empty() ? fs::path(output.string() + ".farm") : fs::absolute(o.workDir);
    // The regions of a render to a quality share one plan, made here once
    // (plan_file.h); a turntable's frames each plan their own.
    const fs::path planFile = target && o.turntable == 0 ? work / "plan.json" : fs::path();
    const RenderCommand command = renderCommand(o, planFile);
    Plan plan = o.turntable > 0
                    ? turntablePlan(command, output, o.turntable)
                    : regionPlan(command, output, work, width, height, std::max(1, o.tiles));
    if (!planFile.empty()) plan.prepare = planTask(command, planFile);
    const bool fresh = startOverIfChanged(plan, work, fingerprint(plan, o.scene));
    if (!fresh && fs::exists(output) && plan.merge) {
        if (!o.quiet) std::cerr << "whitted-farm: " << output.string() << " is already done\n";
        return kExitOk;
    }
    // Another command's, or another scene's, or one this whitted-farm cannot use.
    if (!planFile.empty() && (fresh || !usablePlan(planFile, scene, *target))) fs::remove(planFile);
    SubmitOptions submitOptions{work, o.sbatchArgs, o.maxRunning};
    Jobs jobs;
    try {
        jobs = submit(plan, submitOptions);
    } catch (const std::exception& e) {
        std::cerr << "whitted-farm: " << e.what() << "\n";
        return kExitFailure;
    }
    if (jobs.tasks.empty() && jobs.merge.empty()) {
        if (!o.quiet) std::cerr << "whitted-farm: every frame is already done\n";
        return kExitOk;
    }
    if (!o.quiet) sayQueued(jobs, plan, o.turntable > 0);
    if (!o.wait) return kExitOk;
    // What the plan job chose, once it has (from the file, in the user's words).
    const auto sayPlan = [&] {
        try {
            sayQualityPlan(readPlanFile(planFile, scene, *target));
        } catch (const std::runtime_error& e) {
            std::cerr << "whitted-farm: " << e.what() << "\n";
        }
    };
    // A render taken up again has its plan already: no job makes it.
    if (!o.quiet && !planFile.empty() && jobs.prepare.empty()) {
        std::cerr << "whitted-farm: the plan, made before, in " << planFile.string() << ":\n";
        sayPlan();
    }
    return follow(jobs, plan, work, output, o.quiet, sayPlan);
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "Render a Whitted scene on a Slurm cluster: the image's regions, or a "
        "turntable's frames, as an array job.",
        "whitted-farm"};
    Options o;
    app.add_option("scene", o.scene, "Scene file (JSON, format whitted-scene v1)")
        ->required()
        ->check(CLI::ExistingFile);
    app.add_option("-o,--output", o.output, "Output image (a turntable's: OUT.0001.png, ...)")
        ->required();
    auto* tiles = app.add_option("--tiles", o.tiles, "Render the image as N regions, one task each")
                      ->check(CLI::Range(1, 65536));
    app.add_option("--turntable", o.turntable, "Render N frames of a turntable, one task each")
        ->check(CLI::Range(1, 99999))
        ->excludes(tiles);
    app.add_flag("--wait", o.wait,
                 "Follow the jobs to the end; exit 1, showing the log, if a task fails");
    addRenderFlags(app, o.render);
    addQualityFlags(app, o.quality);
    app.add_option("--max-running", o.maxRunning, "At most K tasks at once (sbatch --array=...%K)")
        ->check(CLI::Range(1, 100000));
    app.add_option("--sbatch-arg", o.sbatchArgs,
                   "Pass an option on to sbatch, e.g. --sbatch-arg=--partition=gpu");
    app.add_option("--work-dir", o.workDir,
                   "Where parts and logs go, on a file system every node shares "
                   "(default: OUT.farm beside the output)");
    app.add_flag("--quiet", o.quiet, "Print nothing but errors");
    if (const auto code = parseFlags(app, "whitted-farm", argc, argv)) return *code;
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    return runOrSay("whitted-farm", [&] { return run(o); });
}
