// Two threads against one: first what this machine gives any program's second
// thread (machine_probes.h), then our renders and, when built with Embree 3,
// the Embree tracer's (embree_tracer.h), each scene at one thread and at two
// in turn, in one run. Not a test.
//   build/bin/bench_threads [--scenes seed,LAYOUT:N,...] [--runs R]
//                           [--width W] [--height H] [--csv FILE]
// Defaults: the seed, and whitted-field's layouts field at 100k and 1M balls,
// clustered and inside at 100k; 1280x720, 1 spp, float, the fastest of 5
// runs a thread count. Our times are whole renders, the scene's preparation and the
// tree's build included, as `whitted-render --stats` reports them, but in one
// process whose memory is reused from render to render. Embree's are its
// high-quality build and render; its build alone is shown apart.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench_args.h"
#include "field_layouts.h"
#include "machine_probes.h"
#include "scene/scene_io.h"
#include "tracer/kernel_dispatch.h"
#include "tracer/renderer.h"
#ifdef WHITTED_HAVE_EMBREE
#include "embree_tracer.h"
#endif

namespace {

using namespace whitted;

struct Options {
    std::vector<std::string> scenes = {"seed", "field:100000", "field:1000000", "clustered:100000",
                                       "inside:100000"};
    int runs = 5;
    int width = 1280, height = 720;
    std::string csv;
};

Options parseOptions(int argc, char** argv) {
    Options o;
    CLI::App app{"Two threads against one: this machine, our tracer and Embree's"};
    app.add_option("--scenes", o.scenes,
                   "seed, or a whitted-field layout and its ball count (field:100000)")
        ->delimiter(',');
    app.add_option("--runs", o.runs, "Runs a thread count; the fastest is shown")
        ->check(CLI::PositiveNumber);
    app.add_option("--width", o.width, "Image width")->check(CLI::PositiveNumber);
    app.add_option("--height", o.height, "Image height")->check(CLI::PositiveNumber);
    app.add_option("--csv", o.csv, "Write the scenes' rows as CSV");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        std::exit(app.exit(e) == 0 ? 0 : 2);
    }
    return o;
}

// A figure at one thread and at two: the fastest of each.
struct Pair {
    double one = 1e300, two = 1e300;
    double speedUp() const { return one / two; }
    bool measured() const { return one < 1e300; }
};

struct Row {
    std::string scene;
    int balls = 0;
    Pair ours, embree, embreeBuild;
};

double oursMs(const Scene& scene, int threads) {
    RenderOptions options = oneShotOptions();
    options.threads = threads;
    return render(scene, options).seconds * 1e3;
}

Row measure(const std::string& name, const Scene& scene, int runs) {
    Row row;
    row.scene = name;
    row.balls = int(scene.spheres.size());
    for (int i = 0; i < runs; ++i)
        for (const int t : {1, 2}) {
            double& ours = t == 1 ? row.ours.one : row.ours.two;
            ours = std::min(ours, oursMs(scene, t));
#ifdef WHITTED_HAVE_EMBREE
            const EmbreeRun e = renderWithEmbree(scene, t);
            double& whole = t == 1 ? row.embree.one : row.embree.two;
            double& build = t == 1 ? row.embreeBuild.one : row.embreeBuild.two;
            whole = std::min(whole, e.renderMs);
            build = std::min(build, e.buildHighMs);
#endif
        }
    return row;
}

std::string cells(const Pair& p) {
    if (!p.measured()) return "        -        -     -";
    char text[64];
    std::snprintf(text, sizeof text, "%9.1f %8.1f %5.2f", p.one, p.two, p.speedUp());
    return text;
}

void printRow(const Row& r) {
    std::printf("%-17s %8d | %s | %s | %s\n", r.scene.c_str(), r.balls, cells(r.ours).c_str(),
                cells(r.embree).c_str(), cells(r.embreeBuild).c_str());
    std::fflush(stdout);
}

void writeCsv(std::FILE* f, const Row& r) {
    std::fprintf(f, "%s,%d,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f\n", r.scene.c_str(), r.balls, r.ours.one,
                 r.ours.two, r.embree.measured() ? r.embree.one : -1.0,
                 r.embree.measured() ? r.embree.two : -1.0,
                 r.embreeBuild.measured() ? r.embreeBuild.one : -1.0,
                 r.embreeBuild.measured() ? r.embreeBuild.two : -1.0);
    std::fflush(f);
}

void printMachine(int runs) {
    std::printf("this machine, the same work on one thread and on each of two (fastest of %d):\n",
                runs);
    for (const bench::ProbeResult& p : bench::probeMachine(runs))
        std::printf("  %-44s %8.1f ms %8.1f ms  speed-up %.2f\n", p.name.c_str(), p.oneThreadMs,
                    p.twoThreadsMs, p.speedUp());
}

// "seed", or "LAYOUT:N" for whitted-field's layout of N balls; nullopt for
// neither.
std::optional<Scene> sceneNamed(const std::string& name, int width, int height) {
    if (name == "seed") {
        Scene seed = loadScene(WHITTED_SCENES_DIR "/seed.json");
        seed.render.width = width;
        seed.render.height = height;
        return seed;
    }
    const std::size_t colon = name.find(':');
    if (colon == std::string::npos) return std::nullopt;
    const int balls = std::atoi(name.c_str() + colon + 1);
    const auto layout = fieldLayout(name.substr(0, colon), balls);
    if (!layout || balls < 1) return std::nullopt;
    return sphereField(*layout, width, height);
}

}  // namespace

int main(int argc, char** argv) {
    const Options o = parseOptions(argc, argv);
    for (const std::string& name : o.scenes)
        if (!sceneNamed(name, 1, 1)) {
            std::fprintf(stderr, "bench_threads: no scene \"%s\" (seed, or LAYOUT:N)\n",
                         name.c_str());
            return 2;
        }
    std::FILE* csv = bench::openCsv(o.csv,
                                    "scene,spheres,ours_1t_ms,ours_2t_ms,embree_1t_ms,"
                                    "embree_2t_ms,embree_build_1t_ms,embree_build_2t_ms");
    printMachine(o.runs);
    std::printf("\n%dx%d, 1 spp, float, kernel %s; fastest of %d runs a thread count\n", o.width,
                o.height, activeKernelName().c_str(), o.runs);
    std::printf("%-17s %8s | %9s %8s %5s | %9s %8s %5s | %9s %8s %5s\n", "scene", "spheres",
                "ours 1t", "2t", "x", "Embree 1t", "2t", "x", "E bld 1t", "2t", "x");
    for (const std::string& name : o.scenes) {
        const Row row = measure(name, *sceneNamed(name, o.width, o.height), o.runs);
        printRow(row);
        if (csv) writeCsv(csv, row);
    }
    if (csv) std::fclose(csv);
    return 0;
}
