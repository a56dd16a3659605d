// whitted-render: renders a scene file to an image (SPEC §7).
// Exit codes: 0 success; 2 bad input (scene or flags); 1 any other failure.
// On failure no output file is left behind.
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "atomic_file.h"
#include "image_io.h"
#include "kernel_dispatch.h"
#include "renderer.h"
#include "scene_io.h"

namespace fs = std::filesystem;
using namespace whitted;

namespace {

constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;
constexpr int kExitBadInput = 2;

struct Options {
    std::string scene;
    std::string output;
    std::optional<int> width, height, spp, depth;
    std::optional<std::string> precision;
    int threads = 0;
    std::string stats;
    bool quiet = false;
};

// A one-line bar on stderr, shown only once a render has run for a second, so
// quick renders print nothing but their summary.
class ProgressBar {
  public:
    explicit ProgressBar(bool enabled) : enabled_(enabled) {}

    void update(double fraction) {
        if (!enabled_) return;
        std::unique_lock lock(mutex_, std::try_to_lock);
        if (!lock) return;  // another worker is drawing; skipping a frame is fine
        const double elapsed = seconds();
        if (elapsed < 1.0 || elapsed - lastDraw_ < 0.1) return;
        lastDraw_ = elapsed;
        draw(fraction, elapsed);
    }

    void finish() {
        std::lock_guard lock(mutex_);
        if (lastDraw_ < 0) return;
        draw(1.0, seconds());
        std::fputc('\n', stderr);
    }

  private:
    double seconds() const {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }

    void draw(double fraction, double elapsed) {
        constexpr int kWidth = 40;
        const int filled = static_cast<int>(fraction * kWidth);
        std::string bar(filled, '#');
        bar.resize(kWidth, '.');
        std::fprintf(stderr, "\r[%s] %3d%%  %.1f s", bar.c_str(), static_cast<int>(fraction * 100),
                     elapsed);
        std::fflush(stderr);
    }

    bool enabled_;
    std::mutex mutex_;
    double lastDraw_ = -1.0;
    const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

void applyOverrides(const Options& o, RenderSettings& r) {
    if (o.width) r.width = *o.width;
    if (o.height) r.height = *o.height;
    if (o.spp) r.samplesPerPixel = *o.spp;
    if (o.depth) r.maxDepth = *o.depth;
    if (o.precision) r.precision = *parsePrecision(*o.precision);
}

std::string statsJson(const RenderSettings& r, const RenderResult& result) {
    const RayCounts& rays = result.rays;
    nlohmann::ordered_json j;
    j["width"] = r.width;
    j["height"] = r.height;
    j["samples_per_pixel"] = r.samplesPerPixel;
    j["max_depth"] = r.maxDepth;
    j["precision"] = std::string(precisionName(r.precision));
    j["threads"] = result.threads;
    j["kernel"] = activeKernelName();
    j["seconds"] = result.seconds;
    j["rays"] = {{"camera", rays.camera},
                 {"shadow", rays.shadow},
                 {"reflection", rays.reflection},
                 {"refraction", rays.refraction},
                 {"total", rays.total()}};
    j["mrays_per_second"] = result.seconds > 0 ? rays.total() / result.seconds / 1e6 : 0.0;
    return j.dump(2) + "\n";
}

void writeText(const fs::path& file, const std::string& text) {
    replaceFileAtomically(file, [&](const fs::path& temp) {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        out << text;
        out.close();
        if (!out) throw std::runtime_error("cannot write file");
    });
}

int run(const Options& o) {
    if (!imageFormatFor(o.output)) {
        std::cerr << "whitted-render: " << o.output
                  << ": unknown image extension (use .png, .jpg, .tif, .exr or .hdr)\n";
        return kExitBadInput;
    }
    Scene scene;
    try {
        scene = loadScene(o.scene);
    } catch (const SceneError& e) {
        std::cerr << "whitted-render: " << e.what() << "\n";
        return kExitBadInput;
    }
    applyOverrides(o, scene.render);

    try {
        // A WHITTED_KERNEL this CPU cannot run, or a WHITTED_ACCEL that names
        // no structure, is refused before rendering, as bad input.
        activeKernel();
        bvhChosen(static_cast<int>(scene.spheres.size()));
    } catch (const std::runtime_error& e) {
        std::cerr << "whitted-render: " << e.what() << "\n";
        return kExitBadInput;
    }
    ProgressBar bar(!o.quiet);
    RenderOptions options;
    options.threads = o.threads;
    options.progressive = false;  // nobody watches the preview here
    const RenderResult result =
        render(scene, options, [&](const TileUpdate& t) { bar.update(t.progress.fraction); });
    bar.finish();

    try {
        writeImage(result.image, o.output,
                   makeImageMetadata(scene.render, result.seconds, "whitted-render"));
    } catch (const std::exception& e) {
        std::cerr << "whitted-render: " << e.what() << "\n";
        return kExitFailure;
    }
    if (!o.stats.empty()) {
        try {
            writeText(o.stats, statsJson(scene.render, result));
        } catch (const std::exception& e) {
            std::cerr << "whitted-render: " << o.stats << ": " << e.what() << "\n";
            std::error_code ignored;
            fs::remove(o.output, ignored);  // a failed run leaves no output behind
            return kExitFailure;
        }
    }
    if (!o.quiet) {
        std::fprintf(
            stderr, "wrote %s: %dx%d, %d spp, depth %d, %s, %.3f s, %.1f Mrays/s, %s kernel\n",
            o.output.c_str(), scene.render.width, scene.render.height, scene.render.samplesPerPixel,
            scene.render.maxDepth, std::string(precisionName(scene.render.precision)).c_str(),
            result.seconds, result.seconds > 0 ? result.rays.total() / result.seconds / 1e6 : 0.0,
            activeKernelName().c_str());
    }
    return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Render a Whitted scene file to an image.", "whitted-render"};
    Options o;
    app.add_option("scene", o.scene, "Scene file (JSON, format whitted-scene v1)")
        ->required()
        ->check(CLI::ExistingFile);
    app.add_option("-o,--output", o.output, "Output image: .png .jpg .tif .exr or .hdr")
        ->required();
    app.add_option("--width", o.width, "Image width in pixels")
        ->check(CLI::Range(1, kMaxImageSize));
    app.add_option("--height", o.height, "Image height in pixels")
        ->check(CLI::Range(1, kMaxImageSize));
    app.add_option("--spp", o.spp, "Samples per pixel")->check(CLI::Range(1, kMaxSamplesPerPixel));
    app.add_option("--depth", o.depth, "Maximum recursion depth")->check(CLI::Range(0, kMaxDepth));
    app.add_option("--precision", o.precision, "Arithmetic of the tracer")
        ->check(CLI::IsMember({"float", "double"}));
    app.add_option("--threads", o.threads, "Worker threads (default: all cores)")
        ->check(CLI::Range(1, 1024));
    app.add_option("--stats", o.stats, "Write render statistics as JSON to this file");
    app.add_flag("--quiet", o.quiet, "Print nothing but errors");

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "whitted-render: " << e.what() << "\n"
                  << "Run with --help for usage.\n";
        return kExitBadInput;
    }
    try {
        return run(o);
    } catch (const std::exception& e) {
        std::cerr << "whitted-render: " << e.what() << "\n";
        return kExitFailure;
    }
}
