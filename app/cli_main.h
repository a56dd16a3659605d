// What every command-line program does the same way: its exit codes (SPEC §7),
// reading its flags, and turning an error that escapes into one line on
// stderr, "<program>: <message>".
#pragma once

#include <exception>
#include <iostream>
#include <optional>
#include <string_view>

#include <CLI/CLI.hpp>

#include "exit_codes.h"

namespace whitted {

// Reads the flags. Nothing when the program should go on; else the exit code,
// having printed the help (0) or what is wrong (kExitBadInput). `check` may
// throw a CLI::ParseError of its own for what CLI11 cannot say (a flag
// required unless a subcommand is given).
template <typename Check = void (*)()>
std::optional<int> parseFlags(
    CLI::App& app, std::string_view program, int argc, char** argv, Check check = [] {}) {
    try {
        app.parse(argc, argv);
        check();
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help (and the like): printed
        std::cerr << program << ": " << e.what() << "\nRun with --help for usage.\n";
        return kExitBadInput;
    }
    return std::nullopt;
}

// run()'s exit code; an exception that escapes it is said and exits 1.
template <typename Run>
int runOrSay(std::string_view program, Run run) {
    try {
        return run();
    } catch (const std::exception& e) {
        std::cerr << program << ": " << e.what() << "\n";
        return kExitFailure;
    }
}

}  // namespace whitted
