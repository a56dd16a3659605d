// A plan's tasks as Slurm jobs (whitted-farm): a job that prepares
// what the tasks share, if the plan has one still to do, an array job of the
// tasks not yet done that depends on it, and a merge job that depends on the
// array (each afterok, and cancelled if what it waits for fails), submitted
// with sbatch; their states read back from squeue; scancel. Every command
// runs without a shell (process.h), and the tasks' own command lines are
// read from files, NUL-separated, so no path is ever parsed as shell.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "plan.h"

namespace whitted::farm {

struct SubmitOptions {
    std::filesystem::path work;           // shared by all nodes: the jobs run in it
    std::vector<std::string> sbatchArgs;  // passed on to every sbatch
    int maxRunning = 0;                   // the array's concurrency limit; 0: none
};

struct Jobs {
    std::string prepare;       // empty: none, or done before
    std::string tasks;         // the array job's id; empty: every task was done
    std::vector<int> indices;  // the tasks it runs (indices into Plan::tasks)
    std::string merge;         // empty: no merge
};

// Writes the work directory's task script and argument files, then submits.
// Throws std::runtime_error with sbatch's exit code when it refuses.
Jobs submit(const Plan& plan, const SubmitOptions& options);

// The state of each task of the jobs as squeue shows them, by its id
// ("12_3" for task 3 of array job 12, "13" for a job), PENDING to COMPLETED.
// Jobs that squeue no longer lists are left out.
std::map<std::string, std::string> jobStates(const Jobs& jobs);

bool finishedState(const std::string& state);  // no longer pending or running
bool failedState(const std::string& state);    // finished without success

void cancelJobs(const Jobs& jobs);

}  // namespace whitted::farm
