// The flags that override a scene's render settings, shared by the programs
// that render one (whitted-render, whitted-farm): declared, applied and
// passed on in one place, so that they read and check alike everywhere.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

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

}  // namespace whitted
