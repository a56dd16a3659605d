// The flags that override a scene's render settings, shared by the programs
// that render one (whitted-render, whitted-farm): declared, applied and
// passed on in one place, so that they read and check alike everywhere.
#pragma once

#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "analysis/quality_target.h"
#include "scene/scene.h"

namespace whitted {

struct RenderFlags {
    std::optional<int> width, height, spp, depth;
    std::optional<std::string> precision;
};

inline void addRenderFlags(CLI::App& app, RenderFlags& f) {
    app.add_option("--width", f.width, "Image width in pixels")
        ->check(CLI::Range(1, kMaxImageSize));
    app.add_option("--height", f.height, "Image height in pixels")
        ->check(CLI::Range(1, kMaxImageSize));
    app.add_option("--spp", f.spp, "Samples per pixel")->check(CLI::Range(1, kMaxSamplesPerPixel));
    app.add_option("--depth", f.depth, "Maximum recursion depth")->check(CLI::Range(0, kMaxDepth));
    app.add_option("--precision", f.precision, "Arithmetic of the tracer")
        ->check(CLI::IsMember({"float", "double"}));
}

inline void applyRenderFlags(const RenderFlags& f, RenderSettings& r) {
    if (f.width) r.width = *f.width;
    if (f.height) r.height = *f.height;
    if (f.spp) r.samplesPerPixel = *f.spp;
    if (f.depth) r.maxDepth = *f.depth;
    if (f.precision) r.precision = *parsePrecision(*f.precision);
}

// The flags as given, to pass on to another program (a farm's tasks).
inline std::vector<std::string> renderFlagArguments(const RenderFlags& f) {
    std::vector<std::string> args;
    const auto add = [&](const char* name, const std::optional<int>& v) {
        if (v) args.insert(args.end(), {name, std::to_string(*v)});
    };
    add("--width", f.width);
    add("--height", f.height);
    add("--spp", f.spp);
    add("--depth", f.depth);
    if (f.precision) args.insert(args.end(), {"--precision", *f.precision});
    return args;
}

// The flags that ask for a render to a quality instead of the
// scene's samples: a preset's target or one of the user's own.
struct QualityFlags {
    std::string quality;  // draft, preview or final; empty: none
    std::optional<double> targetPsnr, maxError;
};

inline void addQualityFlags(CLI::App& app, QualityFlags& f) {
    app.add_option("--quality", f.quality,
                   "Render to a quality: draft (20 dB), preview (35 dB, no pixel off by more "
                   "than 64 codes) or final (50 dB, 16 codes); the depth is chosen for the scene "
                   "and each tile sampled until its error is under the target (--spp: at most "
                   "that many samples a pixel, default 1024; --depth: fix the depth)")
        ->transform(CLI::IsMember({"draft", "preview", "final"}, CLI::ignore_case));
    app.add_option("--target-psnr", f.targetPsnr,
                   "Render to this PSNR in dB of the 8-bit picture against a converged render, "
                   "as --quality does")
        ->check(CLI::Range(1.0, 100.0));
    app.add_option("--max-error", f.maxError,
                   "With --target-psnr: no pixel off by more than this many 8-bit codes")
        ->check(CLI::Range(0.5, 255.0));
}

// The target the flags ask for, if any; std::invalid_argument where they
// contradict each other.
inline std::optional<QualityTarget> qualityTargetOf(const QualityFlags& f) {
    if (!f.quality.empty() && f.targetPsnr)
        throw std::invalid_argument("--quality and --target-psnr: give one or the other");
    if (f.maxError && !f.targetPsnr)
        throw std::invalid_argument("--max-error needs --target-psnr (a preset brings its own)");
    if (!f.quality.empty()) return qualityPreset(f.quality);
    if (f.targetPsnr) return QualityTarget{"", *f.targetPsnr, f.maxError};
    return std::nullopt;
}

// The flags as given, to pass on to another program.
inline std::vector<std::string> qualityFlagArguments(const QualityFlags& f) {
    std::vector<std::string> args;
    if (!f.quality.empty()) args.insert(args.end(), {"--quality", f.quality});
    const auto add = [&](const char* name, const std::optional<double>& v) {
        if (!v) return;
        std::ostringstream text;  // every digit: the task reads back the very number given
        text.precision(17);
        text << *v;
        args.insert(args.end(), {name, text.str()});
    };
    add("--target-psnr", f.targetPsnr);
    add("--max-error", f.maxError);
    return args;
}

}  // namespace whitted
