// render(): the scene traced as whitted-render traces it, into a NumPy array.
// The tracer runs on threads of its own with the GIL released; the calling
// thread waits for it, looking every kPollMs for Ctrl+C and calling the
// progress callback, so both happen in the caller's thread.
#include <pybind11/functional.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "analysis/quality_target.h"
#include "bindings.h"
#include "camera/camera_control.h"
#include "image/image_parts.h"
#include "render_stats.h"
#include "tracer/renderer.h"

namespace whitted::python {

namespace {

constexpr auto kPollMs = std::chrono::milliseconds(50);

// What render() was asked for beyond the scene's own settings, checked as
// whitted-render checks its flags.
struct RenderArgs {
    std::optional<int> width, height, spp, depth;
    std::optional<std::string> precision;
    int threads = 0;
    std::optional<std::string> quality;
    std::optional<double> targetPsnr, maxError;
    std::optional<std::tuple<int, int, int, int>> region;  // x0, y0, x1, y1
};

void checkRange(const char* name, const std::optional<int>& v, int low, int high) {
    if (v && (*v < low || *v > high))
        throw py::value_error(std::string(name) + " must be in [" + std::to_string(low) + ", " +
                              std::to_string(high) + "], not " + std::to_string(*v));
}

// The scene's settings as the arguments change them, checked.
void applyArgs(const RenderArgs& a, RenderSettings& r) {
    checkRange("width", a.width, 1, kMaxImageSize);
    checkRange("height", a.height, 1, kMaxImageSize);
    checkRange("spp", a.spp, 1, kMaxSamplesPerPixel);
    checkRange("depth", a.depth, 0, kMaxDepth);
    if (a.threads < 0) throw py::value_error("threads must be >= 0 (0: all cores)");
    if (a.width) r.width = *a.width;
    if (a.height) r.height = *a.height;
    if (a.spp) r.samplesPerPixel = *a.spp;
    if (a.depth) r.maxDepth = *a.depth;
    if (a.precision) {
        const auto p = parsePrecision(*a.precision);
        if (!p)
            throw py::value_error("precision must be \"float\" or \"double\", not \"" +
                                  *a.precision + "\"");
        r.precision = *p;
    }
}

// The quality target the arguments ask for, if any (whitted-render's
// --quality, --target-psnr and --max-error).
std::optional<QualityTarget> targetOf(const RenderArgs& a) {
    if (a.quality && a.targetPsnr)
        throw py::value_error("quality and target_psnr: give one or the other");
    if (a.maxError && !a.targetPsnr)
        throw py::value_error("max_error needs target_psnr (a preset brings its own)");
    if (a.quality) {
        const auto preset = qualityPreset(*a.quality);
        if (!preset)
            throw py::value_error("quality must be \"draft\", \"preview\" or \"final\", not \"" +
                                  *a.quality + "\"");
        return preset;
    }
    if (a.targetPsnr) {
        if (!(*a.targetPsnr >= 1.0 && *a.targetPsnr <= 100.0))
            throw py::value_error("target_psnr must be in [1, 100] dB");
        if (a.maxError && !(*a.maxError >= 0.5 && *a.maxError <= 255.0))
            throw py::value_error("max_error must be in [0.5, 255] codes");
        return QualityTarget{"", *a.targetPsnr, a.maxError};
    }
    return std::nullopt;
}

std::optional<PixelRect> regionOf(const std::optional<std::tuple<int, int, int, int>>& corners,
                                  const RenderSettings& r) {
    if (!corners) return std::nullopt;
    const auto [x0, y0, x1, y1] = *corners;
    const PixelRect region{x0, y0, x1 - x0, y1 - y0};
    if (!insidePicture(region, r.width, r.height))
        throw py::value_error("region (" + std::to_string(x0) + ", " + std::to_string(y0) + ", " +
                              std::to_string(x1) + ", " + std::to_string(y1) +
                              ") is not a part of the " + std::to_string(r.width) + "x" +
                              std::to_string(r.height) +
                              " image (x0, y0, x1, y1 with x0 < x1, "
                              "y0 < y1)");
    return region;
}

// The tracer's work, done on a thread of its own.
struct Traced {
    RenderResult result;
    std::optional<QualityPlan> plan;
};

// Runs `work` on another thread with the GIL released, while this thread
// checks for signals and reports progress every kPollMs. A signal (Ctrl+C)
// or an exception from `progress` stops the work and is raised here.
Traced traceAside(const std::function<Traced(const StopPredicate&, std::atomic<double>&)>& work,
                  const std::function<void(double)>& progress) {
    std::mutex mutex;
    std::condition_variable finished;
    bool done = false;
    std::atomic<bool> stop{false};
    std::atomic<double> fraction{0.0};
    Traced traced;
    std::exception_ptr failure;
    std::thread tracer([&] {
        try {
            traced = work([&] { return stop.load(); }, fraction);
        } catch (...) {
            failure = std::current_exception();
        }
        std::lock_guard lock(mutex);
        done = true;
        finished.notify_all();
    });
    const auto stopAndJoin = [&] {
        stop = true;
        py::gil_scoped_release release;
        tracer.join();
    };
    for (bool over = false; !over;) {
        {
            py::gil_scoped_release release;
            std::unique_lock lock(mutex);
            over = finished.wait_for(lock, kPollMs, [&] { return done; });
        }
        if (PyErr_CheckSignals() != 0) {
            stopAndJoin();
            throw py::error_already_set();
        }
        if (progress) {
            try {
                progress(over ? 1.0 : fraction.load());
            } catch (...) {
                stopAndJoin();
                throw;
            }
        }
    }
    tracer.join();
    if (failure) std::rethrow_exception(failure);
    return traced;
}

py::object render(const Scene& given, const RenderArgs& args, bool returnStats,
                  const std::function<void(double)>& progress) {
    Scene scene = given;
    applyArgs(args, scene.render);
    raiseIfInvalid(scene);
    const std::optional<QualityTarget> target = targetOf(args);
    const std::optional<PixelRect> region = regionOf(args.region, scene.render);
    const int maxSamples = args.spp.value_or(kDefaultMaxSamples);
    Traced traced = traceAside(
        [&](const StopPredicate& stop, std::atomic<double>& fraction) {
            Traced t;
            RenderOptions options = oneShotOptions();
            options.threads = args.threads;
            if (region) options.regions = {*region};
            if (target) {
                t.plan = planQuality(scene, *target, maxSamples, args.depth, stop);
                applyPlan(*t.plan, scene, options);
            }
            t.result = render(
                scene, options, [&](const TileUpdate& u) { fraction = u.progress.fraction; }, stop);
            return t;
        },
        progress);
    const Image& image = traced.result.image;
    py::array_t<float> array = arrayOf(region ? cropImage(image, *region) : image);
    if (!returnStats) return array;
    py::object stats =
        fromJsonText(renderStats(scene.render, traced.result, traced.plan, std::nullopt).dump());
    // JSON has no infinity, so the file says null for an estimate of no error
    // at all; Python has one, and a script compares the figure as a number.
    if (traced.plan && traced.result.adaptive) {
        const double db = estimatedPsnr(*traced.plan, *traced.result.adaptive);
        if (std::isinf(db)) stats["quality"]["estimated_psnr_db"] = db;
    }
    return py::make_tuple(array, stats);
}

}  // namespace

void bindRender(py::module_& m) {
    m.def(
        "render",
        [](const Scene& scene, std::optional<int> width, std::optional<int> height,
           std::optional<int> spp, std::optional<int> depth, std::optional<std::string> precision,
           int threads, std::optional<std::string> quality, std::optional<double> targetPsnr,
           std::optional<double> maxError, std::optional<std::tuple<int, int, int, int>> region,
           bool returnStats, std::function<void(double)> progress) {
            const RenderArgs args{width,   height,  spp,        depth,    precision,
                                  threads, quality, targetPsnr, maxError, region};
            return render(scene, args, returnStats, progress);
        },
        py::arg("scene"), py::kw_only(), py::arg("width") = py::none(),
        py::arg("height") = py::none(), py::arg("spp") = py::none(), py::arg("depth") = py::none(),
        py::arg("precision") = py::none(), py::arg("threads") = 0, py::arg("quality") = py::none(),
        py::arg("target_psnr") = py::none(), py::arg("max_error") = py::none(),
        py::arg("region") = py::none(), py::arg("return_stats") = false,
        py::arg("progress") = py::none(),
        R"(Renders the scene as whitted-render does, into a float32 array of shape
(height, width, 3): linear RGB, row 0 at the top, equal bit for bit to the
image whitted-render writes (as EXR) for the same settings.

The keywords override the scene's render settings for this render only:
width, height (1 to 16384 pixels), spp (samples a pixel, 1 to 65536; with a
quality, the most a pixel may take, default 1024), depth (0 to 64), precision
("float" or "double"), threads (0: all cores). quality ("draft", "preview" or
"final") or target_psnr (dB against a converged render, 1 to 100) with
max_error (no pixel off by more than this many 8-bit codes) render to a
quality: the depth is chosen for the scene and each tile sampled until it
meets the target. region=(x0, y0, x1, y1) renders that part of the picture
only and returns its pixels, shape (y1 - y0, x1 - x0, 3).

return_stats=True returns (array, stats), stats the dict whitted-render
--stats writes. progress, a callable, is called from this thread with the
fraction done (0 to 1) about 20 times a second.

The GIL is released while the tracer runs. Ctrl+C stops the render and raises
KeyboardInterrupt. Raises ValueError for an invalid scene (naming the field)
or argument.)");

    m.def(
        "turntable",
        [](const Scene& scene, int frames) {
            if (frames < 1) throw py::value_error("frames must be >= 1");
            std::vector<Camera> cameras;
            for (int frame = 1; frame <= frames; ++frame)
                cameras.push_back(turntableCamera(scene.camera, frame, frames));
            return cameras;
        },
        py::arg("scene"), py::arg("frames"),
        "The cameras of a turntable of `frames` frames, as whitted-render --turntable renders\n"
        "them: the eye turned about look_at around the up axis in equal steps of one turn;\n"
        "the first is the scene's own camera.");
}

}  // namespace whitted::python
