// whitted-numerics: renders a scene (the seed by default) scaled and moved over
// wide ranges in float and in double, measures every image against the double
// reference, and writes docs/numerics.md, docs/numerics.csv and the pictures of
// where each precision breaks.
// Exit codes as whitted-render: 0 success; 2 bad input (scene or flags); 1 any
// other failure.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "base/atomic_file.h"
#include "cli_input.h"
#include "cli_main.h"
#include "image/image_io.h"
#include "numerics/difference_picture.h"
#include "numerics/measure.h"
#include "numerics/ranges.h"
#include "numerics/numerics_report.h"
#include "numerics/sweep_plan.h"
#include "scene/scene_io.h"
#include "tracer/renderer.h"

namespace fs = std::filesystem;
using namespace whitted;
using namespace whitted::numerics;

namespace {

constexpr const char* kDefaultScene = "scenes/seed.json";
constexpr const char* kDefaultOutDir = "docs";
constexpr int kDefaultWidth = 320;
constexpr int kDefaultHeight = 240;
// Where the pictures go, relative to the output directory (and so to the report).
constexpr const char* kImageDir = "images/numerics";

struct Options {
    std::string scene = kDefaultScene;
    std::string outDir = kDefaultOutDir;
    int width = kDefaultWidth;
    int height = kDefaultHeight;
    int threads = 0;
    bool quick = false;
    bool quiet = false;
};

// The command that rewrites this very report, for its header.
std::string regenerateCommand(const Options& o) {
    std::string cmd = "build/bin/whitted-numerics";
    if (o.scene != kDefaultScene) cmd += " --scene " + o.scene;
    if (o.outDir != kDefaultOutDir) cmd += " --out-dir " + o.outDir;
    if (o.width != kDefaultWidth) cmd += " --width " + std::to_string(o.width);
    if (o.height != kDefaultHeight) cmd += " --height " + std::to_string(o.height);
    if (o.quick) cmd += " --quick";
    if (cmd == "build/bin/whitted-numerics")
        return "`cmake --build build --target numerics-docs` (builds the program and runs `" + cmd +
               "` in the repository root)";
    return "`" + cmd + "` in the repository root";
}

// The pictures of an earlier run would otherwise linger once the ranges move.
void removeOldPictures(const fs::path& dir) {
    if (!fs::is_directory(dir)) return;
    for (const auto& e : fs::directory_iterator(dir)) {
        const std::string name = e.path().filename().string();
        bool ours = name == "reference.png";
        for (SweepKind kind : kSweepKinds) ours = ours || name.starts_with(sweepId(kind));
        if (ours && e.path().extension() == ".png") fs::remove(e.path());
    }
}

std::string pictureStem(const SweepPoint& p) {
    return std::string(sweepId(p.kind)) + "-" + std::string(precisionName(p.precision)) + "-k" +
           std::to_string(p.k);
}

class Progress {
  public:
    Progress(bool enabled, std::size_t total) : enabled_(enabled), total_(total) {}
    void point(std::size_t index, const PointResult& r) {
        if (!enabled_) return;
        std::fprintf(stderr, "\r[%3zu/%zu] %-9s %-6s k=%-4d %-5s", index + 1, total_,
                     std::string(sweepId(r.point.kind)).c_str(),
                     std::string(precisionName(r.point.precision)).c_str(), r.point.k,
                     meetsBound(r) ? "holds" : "fails");
        std::fflush(stderr);
    }
    void done() {
        if (enabled_) std::fputc('\n', stderr);
    }

  private:
    bool enabled_;
    std::size_t total_;
};

// Re-renders each range's first failing points (rendering is deterministic, so
// this is the measured image) and writes the render and its heat map.
std::vector<Picture> writePictures(const Scene& base, const References& refs,
                                   const std::vector<PointResult>& results,
                                   const std::vector<RangeSummary>& ranges, const fs::path& dir,
                                   int threads) {
    std::vector<Picture> pictures;
    auto add = [&](const RangeSummary& r, int k, const std::string& side) {
        const SweepPoint point{r.kind, r.precision, k};
        const Measurement m = measurePoint(base, point, refs, threads);
        Picture p{m.result, side, {}, {}};
        for (const PointResult& measured : results)
            if (measured.point.kind == r.kind && measured.point.precision == r.precision &&
                measured.point.k == k)
                p.result = measured;  // the sweep's own figures and time
        if (!m.result.refused) {
            const std::string stem = pictureStem(point);
            const ImageMetadata meta = makeImageMetadata(sceneAt(base, point).render,
                                                         m.result.seconds, "whitted-numerics");
            writeImage(m.image, dir / (stem + ".png"), meta);
            writeImage(differencePicture(m.image, refs.doubleImage), dir / (stem + "-diff.png"),
                       meta);
            p.imageFile = std::string(kImageDir) + "/" + stem + ".png";
            p.heatFile = std::string(kImageDir) + "/" + stem + "-diff.png";
        }
        pictures.push_back(std::move(p));
    };
    for (const RangeSummary& r : ranges) {
        if (!r.low) {
            add(r, 0, "k = 0 already fails");
            continue;
        }
        if (r.failBelow) add(r, *r.failBelow, "first failure below the range");
        if (r.failAbove) add(r, *r.failAbove, "first failure above the range");
    }
    return pictures;
}

void printSummary(const std::vector<RangeSummary>& ranges, const fs::path& report) {
    for (const RangeSummary& r : ranges) {
        std::fprintf(stderr, "%-9s %-6s ", std::string(sweepId(r.kind)).c_str(),
                     std::string(precisionName(r.precision)).c_str());
        if (r.low)
            std::fprintf(stderr, "holds for k in [%d, %d] (tested [%d, %d])\n", *r.low, *r.high,
                         r.testedLow, r.testedHigh);
        else
            std::fprintf(stderr, "fails at k = 0\n");
    }
    std::fprintf(stderr, "wrote %s\n", report.string().c_str());
}

int run(const Options& o) {
    std::optional<Scene> loaded = sceneOrSay("whitted-numerics", o.scene);
    if (!loaded) return kExitBadInput;
    Scene& base = *loaded;
    base.render.width = o.width;
    base.render.height = o.height;

    const std::vector<SweepPoint> plan = sweepPlan(o.quick);
    const References refs = renderReferences(base, o.threads);
    std::vector<PointResult> results;
    Progress progress(!o.quiet, plan.size());
    for (std::size_t i = 0; i < plan.size(); ++i) {
        results.push_back(measurePoint(base, plan[i], refs, o.threads).result);
        progress.point(i, results.back());
    }
    progress.done();
    const std::vector<RangeSummary> ranges = summariseRanges(results);

    const fs::path outDir = o.outDir, imageDir = outDir / kImageDir;
    fs::create_directories(imageDir);
    removeOldPictures(imageDir);
    writeImage(refs.doubleImage, imageDir / "reference.png",
               makeImageMetadata(base.render, 0.0, "whitted-numerics"));
    const std::vector<Picture> pictures =
        writePictures(base, refs, results, ranges, imageDir, o.threads);

    ReportContext context;
    context.regenerate = regenerateCommand(o);
    context.sceneName = o.scene;
    context.settings = base.render;
    context.threads = resolveThreadCount(o.threads);
    context.quick = o.quick;
    context.referenceFile = std::string(kImageDir) + "/reference.png";
    context.csvFile = "numerics.csv";
    const fs::path report = outDir / "numerics.md";
    replaceFileWithText(outDir / context.csvFile, csvReport(results));
    replaceFileWithText(report, markdownReport(context, results, ranges, pictures));
    if (!o.quiet) printSummary(ranges, report);
    return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "Measure where float and double renders stop matching the double reference, "
        "over scale and offset sweeps; writes numerics.md, numerics.csv and pictures.",
        "whitted-numerics"};
    Options o;
    app.add_option("--scene", o.scene, "Scene to sweep")
        ->check(CLI::ExistingFile)
        ->capture_default_str();
    app.add_option("--out-dir", o.outDir,
                   "Directory for numerics.md, numerics.csv and images/numerics/")
        ->capture_default_str();
    app.add_option("--width", o.width, "Image width in pixels")
        ->check(CLI::Range(1, kMaxImageSize))
        ->capture_default_str();
    app.add_option("--height", o.height, "Image height in pixels")
        ->check(CLI::Range(1, kMaxImageSize))
        ->capture_default_str();
    app.add_option("--threads", o.threads, "Worker threads (default: all cores)")
        ->check(CLI::Range(1, 1024));
    app.add_flag("--quick", o.quick, "A reduced sweep of a few points each (for tests)");
    app.add_flag("--quiet", o.quiet, "Print nothing but errors");

    if (const auto code = parseFlags(app, "whitted-numerics", argc, argv)) return *code;
    return runOrSay("whitted-numerics", [&] { return run(o); });
}
