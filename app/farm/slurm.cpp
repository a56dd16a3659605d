#include "slurm.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "base/atomic_file.h"
#include "process.h"

namespace whitted::farm {

namespace fs = std::filesystem;

namespace {

// Runs in the work directory (sbatch --chdir): the task's arguments from
// task-<array index>.args, or task-<its argument>.args for the merge and the
// prepare job.
constexpr const char* kTaskScript = R"(#!/bin/bash
# Written by whitted-farm: runs the command in task-<array index>.args (or
# task-merge.args, task-prepare.args), its arguments NUL-separated, with no
# shell in between.
set -euo pipefail
args_file="task-${SLURM_ARRAY_TASK_ID:-$1}.args"
if [[ ! -f $args_file ]]; then
    echo "whitted-farm: $PWD/$args_file is not there on $(hostname): the work directory must be on a file system every node shares" >&2
    exit 1
fi
mapfile -d '' -t args < "$args_file"
exec "${args[@]}"
)";

std::string nulSeparated(const std::vector<std::string>& argv) {
    std::string bytes;
    for (const std::string& a : argv) bytes.append(a).push_back('\0');
    return bytes;
}

// `job`: the task script's argument, naming the arguments file of a job
// that is not the array.
std::string sbatch(const SubmitOptions& o, std::vector<std::string> flags,
                   const std::string& job = {}) {
    std::vector<std::string> argv = {"sbatch", "--parsable", "--chdir=" + o.work.string()};
    argv.insert(argv.end(), flags.begin(), flags.end());
    argv.insert(argv.end(), o.sbatchArgs.begin(), o.sbatchArgs.end());
    argv.push_back((o.work / "task.sh").string());
    if (!job.empty()) argv.push_back(job);
    const ProgramOutput r = runProgram(argv);
    if (r.exitCode != 0)
        throw std::runtime_error("sbatch failed (exit " + std::to_string(r.exitCode) + ")");
    std::string id = r.out.substr(0, r.out.find_first_of(";\n"));
    return id;
}

}  // namespace

Jobs submit(const Plan& plan, const SubmitOptions& o) {
    fs::create_directories(o.work);
    replaceFileWithText(o.work / "task.sh", kTaskScript);
    fs::permissions(o.work / "task.sh", fs::perms::owner_all, fs::perm_options::add);
    Jobs jobs;
    // Waits for `job`, and is cancelled if it fails rather than pending for ever.
    const auto after = [](std::vector<std::string> flags, const std::string& job) {
        if (!job.empty())
            flags.insert(flags.end(), {"--dependency=afterok:" + job, "--kill-on-invalid-dep=yes"});
        return flags;
    };
    if (plan.prepare && !fs::exists(plan.prepare->output)) {
        replaceFileWithText(o.work / "task-prepare.args", nulSeparated(plan.prepare->argv));
        jobs.prepare = sbatch(o, {"--job-name=whitted-prepare", "--output=prepare.log"}, "prepare");
    }
    std::string list;
    for (std::size_t i = 0; i < plan.tasks.size(); ++i) {
        if (fs::exists(plan.tasks[i].output)) continue;  // written atomically: done
        replaceFileWithText(o.work / ("task-" + std::to_string(i) + ".args"),
                            nulSeparated(plan.tasks[i].argv));
        jobs.indices.push_back(static_cast<int>(i));
        // Appended, not "," + ...: GCC 12 warns falsely there (-Wrestrict, bug 105329).
        if (!list.empty()) list.push_back(',');
        list.append(std::to_string(i));
    }
    if (!list.empty()) {
        if (o.maxRunning > 0) list.append("%").append(std::to_string(o.maxRunning));
        jobs.tasks =
            sbatch(o, after({"--job-name=whitted-farm", "--array=" + list, "--output=task-%a.log"},
                            jobs.prepare));
    }
    if (plan.merge) {
        replaceFileWithText(o.work / "task-merge.args", nulSeparated(plan.merge->argv));
        jobs.merge = sbatch(
            o, after({"--job-name=whitted-merge", "--output=merge.log"}, jobs.tasks), "merge");
    }
    return jobs;
}

std::map<std::string, std::string> jobStates(const Jobs& jobs) {
    std::string ids;
    for (const std::string* job : {&jobs.prepare, &jobs.tasks, &jobs.merge})
        if (!job->empty()) ids += (ids.empty() ? "" : ",") + *job;
    std::map<std::string, std::string> states;
    if (ids.empty()) return states;
    const ProgramOutput r = runProgram({"squeue", "-h", "-t", "all", "-j", ids, "-o", "%i %T"});
    std::istringstream lines(r.out);
    for (std::string id, state; lines >> id >> state;) states[id] = state;
    return states;
}

bool finishedState(const std::string& s) {
    return s != "PENDING" && s != "RUNNING" && s != "CONFIGURING" && s != "COMPLETING" &&
           s != "SUSPENDED" && s != "REQUEUED" && s != "RESIZING" && s != "SIGNALING" &&
           s != "STAGE_OUT";
}

bool failedState(const std::string& s) {
    return finishedState(s) && s != "COMPLETED";
}

void cancelJobs(const Jobs& jobs) {
    std::vector<std::string> argv = {"scancel"};
    for (const std::string* job : {&jobs.prepare, &jobs.tasks, &jobs.merge})
        if (!job->empty()) argv.push_back(*job);
    if (argv.size() > 1) runProgram(argv);
}

}  // namespace whitted::farm
