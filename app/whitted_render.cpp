// whitted-render: renders a scene file to an image (SPEC §7), or the frames
// of a turntable, or one region of the image for a farm; `whitted-render
// merge` puts regions back together.
// Exit codes: 0 success; 2 bad input (scene or flags); 1 any other failure.
// On failure no output file is left behind (frames already finished stay).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "analysis/quality_target.h"
#include "base/atomic_file.h"
#include "base/elapsed.h"
#include "base/parallel_for.h"
#include "camera/camera_control.h"
#include "cli_input.h"
#include "cli_main.h"
#include "image/heat_map.h"
#include "image/image_io.h"
#include "image/image_parts.h"
#include "plan_file.h"
#include "ray_tree_json.h"
#include "render/merge.h"
#include "render/progress_bar.h"
#include "render_flags.h"
#include "render_quality.h"
#include "render_stats.h"
#include "scene/scene_io.h"
#include "tracer/kernel_dispatch.h"
#include "tracer/renderer.h"

namespace fs = std::filesystem;
using namespace whitted;

namespace {

struct Options {
    std::string scene;
    std::string output;
    RenderFlags render;  // overrides of the scene's settings
    int threads = 0;
    std::string stats;
    bool quiet = false;
    std::vector<int> region;        // X0, Y0, X1, Y1
    int turntable = 0;              // frames of one full turn; 0: a still
    std::string frames;             // A-B of the turntable's frames; empty: all
    QualityFlags quality;           // a target instead of the scene's samples
    std::string planFile;           // the plan shared with other regions (plan_file.h); empty: none
    std::vector<int> inspect;       // X, Y: print that pixel's ray tree instead of rendering
    std::string sampler = "fixed";  // or whitted1980 (--sampler)
    std::optional<double> threshold;  // whitted1980's, in codes; none: its default
    std::optional<int> subdivisions;  // whitted1980's most cuts of a pixel; none: its default
    std::string subdivisionMap;       // how deep each pixel was cut, as a picture; empty: none
};

// A flag's value is refused: the message, and exit 2.
struct BadInput : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Whitted's 1980 sampling as the flags ask for it, if they do.
std::optional<Whitted1980Sampling> whitted1980Of(const Options& o) {
    if (o.sampler != "whitted1980") return std::nullopt;
    Whitted1980Sampling sampling;
    if (o.threshold) sampling.threshold = *o.threshold;
    if (o.subdivisions) sampling.maxLevels = *o.subdivisions;
    return sampling;
}

// Flags that do not go with the sampler chosen: BadInput.
void checkSamplerFlags(const Options& o) {
    if (o.sampler != "whitted1980") {
        if (o.threshold || o.subdivisions || !o.subdivisionMap.empty())
            throw BadInput(
                "--threshold, --subdivisions and --subdivision-map need --sampler "
                "whitted1980");
        return;
    }
    if (o.render.spp || !o.region.empty() || !o.quality.quality.empty() || o.quality.targetPsnr)
        throw BadInput(
            "--sampler whitted1980 chooses its own rays, at the pixels' corners: "
            "--spp, --region and the quality flags do not go with it");
}

// The region flag as pixels of the image, checked against its size.
std::optional<PixelRect> regionOf(const Options& o, const RenderSettings& r) {
    if (o.region.empty()) return std::nullopt;
    const PixelRect region{o.region[0], o.region[1], o.region[2] - o.region[0],
                           o.region[3] - o.region[1]};
    if (!insidePicture(region, r.width, r.height))
        throw BadInput("--region " + cornersText(region) + ": not a part of the " +
                       std::to_string(r.width) + "x" + std::to_string(r.height) +
                       " image (X0,Y0,X1,Y1 with X0 < X1, Y0 < Y1)");
    return region;
}

// The frames to render, first to last: {0, 0} for a still.
std::pair<int, int> framesOf(const Options& o) {
    if (o.turntable == 0) {
        if (!o.frames.empty()) throw BadInput("--frames needs --turntable N");
        return {0, 0};
    }
    if (o.frames.empty()) return {1, o.turntable};
    int first = 0, last = 0;
    char dash = 0, rest = 0;
    std::istringstream in(o.frames);
    if (!(in >> first >> dash >> last) || dash != '-' || in >> rest || first < 1 || last < first ||
        last > o.turntable)
        throw BadInput("--frames " + o.frames +
                       ": not A-B with 1 <= A <= B <= " + std::to_string(o.turntable));
    return {first, last};
}

// What was written, on stderr: the picture, its samples, depth and precision, the time.
void sayWritten(const fs::path& output, const RenderSettings& r,
                const std::optional<PixelRect>& region, const RenderResult& result,
                const RenderOptions& options, const std::optional<QualityPlan>& plan) {
    if (plan && result.adaptive) sayQualityReached(*plan, *result.adaptive);
    // "640x480", or "region 0,0,320,240 of 640x480".
    const std::string picture =
        (region ? "region " + cornersText(*region) + " of " : std::string()) +
        std::to_string(r.width) + "x" + std::to_string(r.height);
    if (options.whitted1980) {
        std::fprintf(stderr,
                     "wrote %s: %s, Whitted 1980 sampling (threshold %g codes, at most %d "
                     "subdivisions): %.2f camera rays a pixel, depth %d, %s, %.3f s\n",
                     output.c_str(), picture.c_str(), options.whitted1980->threshold,
                     options.whitted1980->maxLevels, cameraRaysPerPixel(r, result), r.maxDepth,
                     std::string(precisionName(r.precision)).c_str(), result.seconds);
    } else if (!plan) {
        std::fprintf(stderr,
                     "wrote %s: %s, %d spp, depth %d, %s, %.3f s, %.1f Mrays/s, %s kernel\n",
                     output.c_str(), picture.c_str(), r.samplesPerPixel, r.maxDepth,
                     std::string(precisionName(r.precision)).c_str(), result.seconds,
                     result.seconds > 0 ? result.rays.total() / result.seconds / 1e6 : 0.0,
                     activeKernelName().c_str());
    } else {
        std::fprintf(stderr, "wrote %s: %s, %.1f spp on average, depth %d, %s, %.3f s\n",
                     output.c_str(), picture.c_str(), result.adaptive->meanSamples, r.maxDepth,
                     std::string(precisionName(r.precision)).c_str(), result.seconds);
    }
}

// One image: the scene as given (at the plan's depth, if there is a plan),
// rendered (only its region, if any) and written with its stats. Returns the
// exit code.
int renderFrame(Scene& scene, const Options& o, const std::optional<PixelRect>& region, int frame,
                const std::optional<QualityPlan>& plan) {
    const fs::path output = frameFile(o.output, frame);
    ProgressBar bar(!o.quiet);
    RenderOptions options = oneShotOptions();
    options.threads = o.threads;
    if (region) options.regions = {*region};
    if (plan) applyPlan(*plan, scene, options);
    // The file's spheres, lights and materials were validated as it was
    // read, and since then only the settings changed; if those break a rule,
    // render() checks the whole scene and says which.
    options.sceneValidated = !validateSettingsEdit(scene);
    options.whitted1980 = whitted1980Of(o);
    const RenderResult result =
        render(scene, options, [&](const TileUpdate& t) { bar.update(t.progress.fraction); });
    bar.finish();
    const ImageMetadata metadata =
        plan && result.adaptive
            ? qualityMetadata(scene, *plan, *result.adaptive, result.seconds, "whitted-render")
            : makeImageMetadata(scene.render, result.seconds, "whitted-render");
    try {
        if (region)
            writeImagePart({cropImage(result.image, *region), *region, scene.render.width,
                            scene.render.height, metadata},
                           output, metadata);
        else
            writeImage(result.image, output, metadata);
    } catch (const std::exception& e) {
        std::cerr << "whitted-render: " << e.what() << "\n";
        return kExitFailure;
    }
    if (!o.stats.empty()) {
        const fs::path stats = frameFile(o.stats, frame);
        try {
            replaceFileWithText(
                stats, renderStats(scene.render, result, plan, options.whitted1980).dump(2) + "\n");
        } catch (const std::exception& e) {  // "<stats file>: <reason>"
            std::cerr << "whitted-render: " << e.what() << "\n";
            std::error_code ignored;
            fs::remove(output, ignored);  // a failed run leaves no output behind
            return kExitFailure;
        }
    }
    if (!o.subdivisionMap.empty()) {
        const fs::path map = frameFile(o.subdivisionMap, frame);
        try {
            writeImage(countMap(result.subdivision.levels, scene.render.width, scene.render.height,
                                options.whitted1980->maxLevels),
                       map, {});
        } catch (const std::exception& e) {
            std::cerr << "whitted-render: " << e.what() << "\n";
            return kExitFailure;
        }
    }
    if (!o.quiet) sayWritten(output, scene.render, region, result, options, plan);
    return kExitOk;
}

// A WHITTED_KERNEL this CPU cannot run, or a WHITTED_ACCEL that names no
// structure, is refused before rendering (or planning), as bad input.
void checkTracerChoice(const Scene& scene) {
    activeKernel();
    bvhChosen(static_cast<int>(scene.spheres.size()));
}

// sharedPlan() for `--plan` into `shared`, or what went wrong said: exit 1
// when the file cannot be written, 2 when it holds no plan for this picture.
int sharedPlanOrSay(const Options& o, const Scene& scene, const QualityTarget& target,
                    SharedPlan& shared) {
    try {
        shared = sharedPlan(o.planFile, scene, target, o.render.spp.value_or(kDefaultMaxSamples),
                            o.render.depth);
        return kExitOk;
    } catch (const std::system_error& e) {  // written, not read; what() names the temporary file
        std::cerr << "whitted-render: " << o.planFile
                  << ": cannot write the plan: " << e.code().message() << "\n";
        return kExitFailure;
    } catch (const std::runtime_error& e) {
        std::cerr << "whitted-render: " << e.what() << "\n";
        return kExitBadInput;
    }
}

// `--plan FILE` without -o: the plan made and written there (or found there
// already), nothing rendered. whitted-farm's plan job runs this before its
// tasks.
int runPlanOnly(const Options& o) {
    std::optional<Scene> loaded = sceneOrSay("whitted-render", o.scene);
    if (!loaded) return kExitBadInput;
    Scene& scene = *loaded;
    applyRenderFlags(o.render, scene.render);
    std::optional<QualityTarget> target;
    try {
        target = qualityTargetOf(o.quality);
        if (!target) throw BadInput("--plan needs --quality or --target-psnr");
        if (!o.region.empty() || o.turntable > 0 || !o.stats.empty())
            throw BadInput(
                "--plan without --output only plans: --region, --turntable and "
                "--stats need an image to render");
        checkTracerChoice(scene);
    } catch (const std::exception& e) {
        std::cerr << "whitted-render: " << e.what() << "\n";
        return kExitBadInput;
    }
    SharedPlan shared;
    if (const int code = sharedPlanOrSay(o, scene, *target, shared); code != kExitOk) return code;
    if (!o.quiet) {
        sayQualityPlan(shared.plan);
        std::fprintf(stderr, shared.read ? "the plan in %s was made before\n" : "wrote %s\n",
                     o.planFile.c_str());
    }
    return kExitOk;
}

// `--inspect X,Y`: the pixel's ray tree on stdout as JSON, no image.
int runInspect(const Options& o) {
    std::optional<Scene> loaded = sceneOrSay("whitted-render", o.scene);
    if (!loaded) return kExitBadInput;
    Scene& scene = *loaded;
    applyRenderFlags(o.render, scene.render);
    try {
        if (!o.output.empty() || !o.region.empty() || o.turntable > 0 || !o.stats.empty() ||
            !o.planFile.empty() || qualityTargetOf(o.quality))
            throw BadInput(
                "--inspect prints one pixel's ray tree and renders no image: -o, --region, "
                "--turntable, --stats, --plan and the quality flags do not go with it");
        checkTracerChoice(scene);
        std::cout << rayTreeJson(pixelRayTree(scene, o.inspect[0], o.inspect[1]), scene).dump(2)
                  << "\n";
    } catch (const std::out_of_range& e) {
        std::cerr << "whitted-render: --inspect: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const std::invalid_argument& e) {  // the quality flags
        std::cerr << "whitted-render: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const std::runtime_error& e) {
        std::cerr << "whitted-render: " << e.what() << "\n";
        return kExitBadInput;
    }
    return kExitOk;
}

int run(const Options& o) {
    // Reading the scene and writing the image keep to --threads too.
    processThreadLimit = o.threads;
    if (!o.inspect.empty()) return runInspect(o);
    if (o.output.empty()) return runPlanOnly(o);
    const auto format = outputFormatOrSay("whitted-render", o.output);
    if (!format) return kExitBadInput;
    std::optional<Scene> loaded = sceneOrSay("whitted-render", o.scene);
    if (!loaded) return kExitBadInput;
    Scene& scene = *loaded;
    applyRenderFlags(o.render, scene.render);
    std::optional<PixelRect> region;
    std::pair<int, int> frames;
    try {
        region = regionOf(o, scene.render);
        if (region && format->format != ImageFormat::Exr)
            throw BadInput(o.output +
                           ": --region writes OpenEXR (.exr), which records where "
                           "the region belongs");
        frames = framesOf(o);
        checkSamplerFlags(o);
        checkTracerChoice(scene);
    } catch (const std::runtime_error& e) {
        std::cerr << "whitted-render: " << e.what() << "\n";
        return kExitBadInput;
    }
    std::optional<QualityTarget> target;
    try {
        target = qualityTargetOf(o.quality);
        if (!o.planFile.empty() && !target)
            throw std::invalid_argument("--plan needs --quality or --target-psnr");
        if (!o.planFile.empty() && o.turntable > 0)
            throw std::invalid_argument("--plan: each frame of a turntable has a plan of its own");
    } catch (const std::invalid_argument& e) {
        std::cerr << "whitted-render: " << e.what() << "\n";
        return kExitBadInput;
    }
    const Camera camera = scene.camera;
    const int maxSamples = o.render.spp.value_or(kDefaultMaxSamples);
    for (int frame = frames.first; frame <= frames.second; ++frame) {
        if (frame > 0) scene.camera = turntableCamera(camera, frame, o.turntable);
        std::optional<QualityPlan> plan;
        if (target && o.planFile.empty())
            plan = planQuality(scene, *target, maxSamples, o.render.depth);
        else if (target) {
            SharedPlan shared;
            if (const int code = sharedPlanOrSay(o, scene, *target, shared); code != kExitOk)
                return code;
            if (!o.quiet && shared.read)
                std::fprintf(stderr, "the plan in %s, made before for this picture:\n",
                             o.planFile.c_str());
            plan = shared.plan;
        }
        if (plan && !o.quiet) sayQualityPlan(*plan);
        if (const int code = renderFrame(scene, o, region, frame, plan); code != kExitOk)
            return code;
    }
    return kExitOk;
}

// --sampler and the flags of Whitted's 1980 sampling.
void addSamplerFlags(CLI::App& app, Options& o) {
    app.add_option("--sampler", o.sampler,
                   "How a pixel is sampled: fixed (the scene's samples per pixel, or a quality's "
                   "own) or whitted1980 (Whitted's adaptive antialiasing: rays at the pixels' "
                   "corners, a pixel cut in four where they differ)")
        ->check(CLI::IsMember({"fixed", "whitted1980"}));
    app.add_option("--threshold", o.threshold,
                   "whitted1980: cut a pixel where its corners differ by more than this many "
                   "8-bit codes in a channel (default 8)")
        ->check(CLI::Range(0.0, 255.0));
    app.add_option("--subdivisions", o.subdivisions,
                   "whitted1980: cut a pixel at most this many times (default 2)")
        ->check(CLI::Range(0, kMaxWhitted1980Levels));
    app.add_option("--subdivision-map", o.subdivisionMap,
                   "whitted1980: also write how deep each pixel was cut, black none to pale "
                   "yellow the most, as an image");
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Render a Whitted scene file to an image.", "whitted-render"};
    Options o;
    // Not marked required: `whitted-render merge` has neither (checked below).
    app.add_option("scene", o.scene, "Scene file (JSON, format whitted-scene v1)")
        ->check(CLI::ExistingFile);
    app.add_option("-o,--output", o.output,
                   "Output image: .png .jpg .tif .exr or .hdr; a turntable's frames get "
                   "numbers before the extension (out.0001.png)");
    addRenderFlags(app, o.render);
    app.add_option(
           "--threads", o.threads,
           "Threads reading, preparing and rendering the scene and writing the image (default: "
           "all cores)")
        ->check(CLI::Range(1, 1024));
    app.add_option("--stats", o.stats, "Write render statistics as JSON to this file");
    app.add_flag("--quiet", o.quiet, "Print nothing but errors");
    app.add_option("--region", o.region,
                   "Render only pixels X0 <= x < X1, Y0 <= y < Y1 of the image, into an OpenEXR "
                   "file that records where they belong (see merge)")
        ->delimiter(',')
        ->expected(4);
    app.add_option("--turntable", o.turntable,
                   "Render N frames, the eye turning about look_at once around the up axis")
        ->check(CLI::Range(1, 99999));
    app.add_option("--frames", o.frames, "Render only frames A-B of the turntable (1-based)");
    addQualityFlags(app, o.quality);
    app.add_option("--plan", o.planFile,
                   "With a quality: render to the plan in this file, or plan and write it there "
                   "if there is none, so that the regions of one picture share one plan "
                   "(whitted-farm makes it once for all its tasks); without --output, only plan");

    addSamplerFlags(app, o);

    app.add_option("--inspect", o.inspect,
                   "Print the ray tree of pixel X,Y (0,0 top left) of a one-sample render as "
                   "JSON, and render no image")
        ->delimiter(',')
        ->expected(2);

    MergeOptions m;
    CLI::App* merge = addMergeCommand(app, m);

    if (const auto code = parseFlags(app, "whitted-render", argc, argv, [&] {
            if (!*merge && o.scene.empty()) throw CLI::RequiredError("scene");
            if (!*merge && o.output.empty() && o.planFile.empty() && o.inspect.empty())
                throw CLI::RequiredError("--output");
        }))
        return *code;
    return runOrSay("whitted-render", [&] { return *merge ? runMerge(m) : run(o); });
}
