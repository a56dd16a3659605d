// The converged references that renders to a quality are judged against,
// kept between runs: bench_quality, bench_quality_fields and
// test_quality_target use them. At 640x480 a reference takes minutes, the
// renders it judges seconds; so with WHITTED_REFERENCE_CACHE set to a
// folder, each is kept there as OpenEXR by name and size and read back on
// the next run, and trying a change to the sampling then costs only the
// renders. The test suite renders its references anew each run
// (make_quality_references), so that they come from the code under test.
#pragma once

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "analysis/quality_check.h"
#include "image/image_io.h"

namespace whitted {

// Where the scene's reference is kept: in WHITTED_REFERENCE_CACHE's folder,
// `name` (which scene it is; letters and digits kept, the rest dashes), then
// the size and the depth. Empty when the variable is not set.
inline std::filesystem::path cachedReferenceFile(const Scene& scene, std::string name) {
    const char* folder = std::getenv("WHITTED_REFERENCE_CACHE");
    if (!folder) return {};
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '-';
    return std::filesystem::path(folder) / (name + "-" + std::to_string(scene.render.width) + "x" +
                                            std::to_string(scene.render.height) + "-depth" +
                                            std::to_string(kDeepReferenceDepth) + ".exr");
}

// The scene in double, 512 samples a pixel, kDeepReferenceDepth: read from
// its cachedReferenceFile() if there is one, rendered (and kept) otherwise.
inline Image cachedReference(const Scene& scene, const std::string& name) {
    const std::filesystem::path file = cachedReferenceFile(scene, name);
    if (file.empty()) return convergedReference(scene, 512, kDeepReferenceDepth);
    if (std::filesystem::exists(file)) return readImage(file);
    std::filesystem::create_directories(file.parent_path());
    Image reference = convergedReference(scene, 512, kDeepReferenceDepth);
    writeImage(reference, file, {});
    return reference;
}

}  // namespace whitted
