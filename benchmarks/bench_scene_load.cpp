// Opening a large scene file: writes a scene of N spheres with
// saveScene, then loads it with loadScene in a fresh process, three times, and
// prints the load time and that process's peak memory. A fresh process per
// load, because the writing side's memory would otherwise hide the loader's.
// Prints its figures; not a test.
//   build/bin/bench_scene_load [N ...]      (default 100000 1000000)
//   build/bin/bench_scene_load --load FILE  (one load, the child's part)
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "big_scene.h"
#include "scene/scene_io.h"

extern char** environ;

namespace {

namespace fs = std::filesystem;

// VmHWM, not getrusage's ru_maxrss: Linux keeps ru_maxrss across exec, so a
// child would report the peak of the parent that wrote the file.
long peakResidentKb() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmHWM:", 0) == 0) return std::atol(line.c_str() + 6);
    return -1;
}

int loadOnce(const char* file) {
    const auto start = std::chrono::steady_clock::now();
    const whitted::Scene scene = whitted::loadScene(file);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("%zu %.0f %.0f\n", scene.spheres.size(), ms, peakResidentKb() / 1024.0);
    return 0;
}

struct Load {
    double ms = 0, peakMb = 0;
};

// Runs `self --load file` and reads back the line loadOnce() prints.
Load loadInChild(std::string self, const fs::path& file) {
    const fs::path out = file.string() + ".out";
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    std::string loadFlag = "--load", path = file.string();
    char* argv[] = {self.data(), loadFlag.data(), path.data(), nullptr};
    pid_t pid = 0;
    if (posix_spawn(&pid, self.c_str(), &actions, nullptr, argv, environ) != 0) std::exit(1);
    posix_spawn_file_actions_destroy(&actions);
    int status = 0;
    waitpid(pid, &status, 0);
    Load load;
    size_t spheres = 0;
    FILE* f = std::fopen(out.c_str(), "r");
    if (!f || std::fscanf(f, "%zu %lf %lf", &spheres, &load.ms, &load.peakMb) != 3) std::exit(1);
    std::fclose(f);
    fs::remove(out);
    return load;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc == 3 && std::string(argv[1]) == "--load") return loadOnce(argv[2]);
    std::vector<int> counts;
    for (int i = 1; i < argc; ++i) counts.push_back(std::atoi(argv[i]));
    if (counts.empty()) counts = {100000, 1000000};
    const std::string self = fs::read_symlink("/proc/self/exe");
    const fs::path file =
        fs::temp_directory_path() / ("whitted-bench-scene-load-" + std::to_string(getpid()));
    std::printf("%9s %9s %12s %12s %12s\n", "spheres", "file MB", "fastest ms", "median ms",
                "peak RSS MB");
    for (int count : counts) {
        whitted::saveScene(whitted::bench::bigScene(count), file);
        std::vector<Load> loads;
        for (int run = 0; run < 3; ++run) loads.push_back(loadInChild(self, file));
        std::sort(loads.begin(), loads.end(), [](auto& a, auto& b) { return a.ms < b.ms; });
        std::printf("%9d %9.1f %12.0f %12.0f %12.0f\n", count + 1,
                    double(fs::file_size(file)) / (1 << 20), loads[0].ms, loads[1].ms,
                    loads[1].peakMb);
        fs::remove(file);
    }
    return 0;
}
