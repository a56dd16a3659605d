// Small helpers shared by the tests: a per-test temporary directory, file I/O,
// the seed scene's path, and the programs under test run through the shell.
// Free of the core's types, so that any test executable can include it.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

namespace whitted::test {

// Whether this is a sanitizer build (the ASan and TSan stages). They check
// what a test's code touches, not the numbers it computes, which the Release
// stage checks: a test whose cost is numerical size alone (a converged
// reference, every sample of a large field) does less under them
// (docs/design/testing.md).
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif

// Names of the entries in `dir`, sorted.
inline std::vector<std::string> directoryEntries(const std::filesystem::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// A fresh directory under the system temp dir, named after the running test,
// removed with everything in it when the object goes away.
class TempDir {
  public:
    TempDir() {
        static std::atomic<unsigned> counter{0};
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        std::string name =
            "whitted-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
        if (info) name += std::string("-") + info->test_suite_name() + "-" + info->name();
        for (char& c : name)
            if (c == '/' || c == ' ') c = '_';
        path_ = std::filesystem::temp_directory_path() / name;
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

    // Names of the entries in the directory, sorted.
    std::vector<std::string> entries() const { return directoryEntries(path_); }

  private:
    std::filesystem::path path_;
};

inline std::string readFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

inline void writeFile(const std::filesystem::path& file, const std::string& text) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out << text;
}

// The repository's seed scene (scenes/seed.json), the one most tests start from.
inline const std::string kSeedScenePath = WHITTED_SCENES_DIR "/seed.json";

// The string as one shell word, quoted so that the shell takes it literally.
inline std::string shellQuote(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

// The program and its arguments as one shell command, every word quoted.
// Appended piece by piece: GCC 12 warns falsely (-Wrestrict, bug 105329) on
// "literal" + std::string chains at -O3.
inline std::string commandLine(const std::string& program, const std::vector<std::string>& args) {
    std::string command = shellQuote(program);
    for (const std::string& a : args) command.append(" ").append(shellQuote(a));
    return command;
}

// `args` followed by `more`: a command's arguments put together.
inline std::vector<std::string> appended(std::vector<std::string> args,
                                         const std::vector<std::string>& more) {
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

struct ProgramRun {
    int exitCode = -1;  // -1: it could not start, or a signal ended it
    std::string out;    // its standard output (with its standard error, when merged)
    std::string err;    // its standard error, when captured apart
};

// `command` run by the shell, its standard output captured (append " 2>&1"
// for its standard error too).
inline ProgramRun runShell(const std::string& command) {
    ProgramRun r;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return {-1, "cannot start: " + command, {}};
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
        r.out.append(buffer, n);
    const int status = pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

enum class Stderr { Apart, Merged };

// The program run with the arguments (each one word, whatever it holds), its
// standard output captured, and its standard error either apart (in a file of
// the system temp dir, never one a test looks at) or merged into `out`.
// `environment` ("NAME=value ...", already quoted) goes before the command.
inline ProgramRun runProgram(const std::string& program, const std::vector<std::string>& args,
                             Stderr stderrGoes = Stderr::Apart,
                             const std::string& environment = "") {
    std::string command = environment;
    if (!command.empty()) command.append(" ");
    command.append(commandLine(program, args));
    if (stderrGoes == Stderr::Merged) return runShell(command.append(" 2>&1"));
    static std::atomic<unsigned> counter{0};
    const std::filesystem::path errFile =
        std::filesystem::temp_directory_path() /
        ("whitted-stderr-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    ProgramRun r = runShell(command.append(" 2>").append(shellQuote(errFile.string())));
    r.err = readFile(errFile);
    std::error_code ignored;
    std::filesystem::remove(errFile, ignored);
    return r;
}

// A program under test and where its standard error goes: called with the
// arguments (and an optional environment), it runs as runProgram does.
struct Program {
    std::string path;
    Stderr stderrGoes = Stderr::Apart;
    ProgramRun operator()(const std::vector<std::string>& args,
                          const std::string& environment = "") const {
        return runProgram(path, args, stderrGoes, environment);
    }
};

inline std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
    return "[" + out + "]";
}

}  // namespace whitted::test
