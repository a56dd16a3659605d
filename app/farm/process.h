// Running a program with its arguments as given, never through a shell: a
// scene path with spaces, quotes or $ in it reaches the program intact.
#pragma once

#include <string>
#include <vector>

namespace whitted::farm {

struct ProgramOutput {
    int exitCode = -1;  // -1: it could not be started, or a signal ended it
    std::string out;    // its standard output
};

// Runs argv[0] (looked up on PATH) with argv, waits for it, and returns its
// exit code and standard output; its standard error goes to ours.
ProgramOutput runProgram(const std::vector<std::string>& argv);

}  // namespace whitted::farm
