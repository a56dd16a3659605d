// What an image file records about how it was made: the render's settings,
// time and, for a render to a quality, what it reached. Apart from
// image_io.h, which writes it through OpenImageIO, so that what only
// describes a render (analysis/quality_target.h) does not load OpenImageIO
// and the 255 shared libraries Debian's build of it brings.
#pragma once

#include <string>

#include "scene/scene.h"

namespace whitted {

// What the file records about how it was made.
struct ImageMetadata {
    std::string software = "whitted";
    std::string description;  // human-readable render settings and time
    RenderSettings settings;
    double renderSeconds = 0.0;
    // A render to a quality (analysis/quality_target.h): its target and what
    // it reached, in words ("whitted:quality_target", "whitted:quality_reached",
    // and the two as one line in "whitted:quality"); both empty for a render of
    // the scene's own samples. settings.samplesPerPixel then holds the most
    // samples any pixel took.
    std::string qualityTarget;
    std::string qualityReached;
};

// Builds the description line from the settings and time (and the quality,
// if given, in place of the samples and depth).
ImageMetadata makeImageMetadata(const RenderSettings& settings, double renderSeconds,
                                std::string software, std::string qualityTarget = {},
                                std::string qualityReached = {});

// The target and what was reached as one line: "Final: ...; depth 6, ...";
// empty for a render of the scene's own samples.
std::string qualityLine(const ImageMetadata& metadata);

}  // namespace whitted
