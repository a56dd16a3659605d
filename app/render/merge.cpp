#include "render/merge.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <stdexcept>

#include <CLI/CLI.hpp>

#include "cli_input.h"
#include "exit_codes.h"
#include "image/image_io.h"
#include "image/image_parts.h"

namespace whitted {

namespace {

// What the merged picture of a render to a quality reached: what each part
// reached ("4 regions, each rendered to it: depth 6, ...; depth 6, ..."),
// under the target they share; empty for fixed samples. Parts of other
// targets, or some of fixed samples, are another render's: refused.
std::string mergedReached(const std::vector<ImagePart>& parts,
                          const std::vector<std::string>& names) {
    const std::string& target = parts[0].metadata.qualityTarget;
    const auto what = [](const std::string& t) {
        return t.empty() ? std::string("fixed samples") : "a quality (" + t + ")";
    };
    std::string reached;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const ImageMetadata& m = parts[i].metadata;
        if (m.qualityTarget != target)
            throw std::invalid_argument(names[i] + " was rendered to " + what(m.qualityTarget) +
                                        ", " + names[0] + " to " + what(target) +
                                        ": parts of different renders");
        if (!m.qualityReached.empty()) reached += "; " + m.qualityReached;
    }
    if (target.empty()) return {};
    return std::to_string(parts.size()) + " regions, each rendered to it" +
           (reached.empty() ? "" : ":" + reached.substr(1));
}

}  // namespace

int runMerge(const MergeOptions& o) {
    if (!outputFormatOrSay("whitted-render", o.output)) return kExitBadInput;
    std::vector<ImagePart> parts;
    Image whole;
    std::string reached;
    try {
        for (const std::string& file : o.parts) parts.push_back(readImagePart(file));
        whole = mergeParts(parts, o.parts);
        reached = mergedReached(parts, o.parts);
    } catch (const std::exception& e) {
        std::cerr << "whitted-render: merge: " << e.what() << "\n";
        return kExitBadInput;
    }
    // The settings the parts record (rendered to a quality, each part's
    // depth and most samples its own: the largest of them); the time, all of
    // theirs together.
    RenderSettings settings = parts[0].metadata.settings;
    double seconds = 0.0;
    for (const ImagePart& p : parts) {
        seconds += p.metadata.renderSeconds;
        settings.samplesPerPixel =
            std::max(settings.samplesPerPixel, p.metadata.settings.samplesPerPixel);
        settings.maxDepth = std::max(settings.maxDepth, p.metadata.settings.maxDepth);
    }
    try {
        writeImage(whole, o.output,
                   makeImageMetadata(settings, seconds, "whitted-render",
                                     parts[0].metadata.qualityTarget, reached));
    } catch (const std::exception& e) {
        std::cerr << "whitted-render: " << e.what() << "\n";
        return kExitFailure;
    }
    if (!o.quiet)
        std::fprintf(stderr, "wrote %s: %dx%d from %zu parts\n", o.output.c_str(), whole.width,
                     whole.height, parts.size());
    return kExitOk;
}

CLI::App* addMergeCommand(CLI::App& app, MergeOptions& m) {
    CLI::App* merge = app.add_subcommand(
        "merge", "Put the regions of one picture (--region parts) together into one image");
    merge->add_option("parts", m.parts, "The parts: OpenEXR files from --region")
        ->required()
        ->check(CLI::ExistingFile);
    merge->add_option("-o,--output", m.output, "The whole image: .png .jpg .tif .exr or .hdr")
        ->required();
    merge->add_flag("--quiet", m.quiet, "Print nothing but errors");
    return merge;
}

}  // namespace whitted
