// The command-line programs' exit codes (SPEC §7), apart from cli_main.h so
// that a file can return them without compiling CLI11.
#pragma once

namespace whitted {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;        // anything but the input
inline constexpr int kExitBadInput = 2;       // a flag, a scene or a file the user named
inline constexpr int kExitInterrupted = 130;  // Ctrl+C, as a shell reports it

}  // namespace whitted
