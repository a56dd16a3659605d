// The converged references the quality benches judge against, kept between
// runs (issue 15): shared by bench_quality and bench_quality_fields.
// At 640x480 a reference takes minutes, the renders it judges seconds; so
// with WHITTED_REFERENCE_CACHE set to a folder, each is kept there as
// OpenEXR by name and size and read back on the next run, and trying a
// change to the sampling then costs only the renders.
#pragma once

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "analysis/quality_check.h"
#include "image/image_io.h"

namespace whitted::bench {

// The scene in double, 512 samples a pixel, kDeepReferenceDepth; `name`
// says which scene it is, as the file's name in the cache (letters and
// digits kept, the rest dashes, then the size and the depth).
inline Image cachedReference(const Scene& scene, std::string name) {
    const char* folder = std::getenv("WHITTED_REFERENCE_CACHE");
    if (!folder) return convergedReference(scene, 512, kDeepReferenceDepth);
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '-';
    const std::filesystem::path file =
        std::filesystem::path(folder) / (name + "-" + std::to_string(scene.render.width) + "x" +
                                         std::to_string(scene.render.height) + "-depth" +
                                         std::to_string(kDeepReferenceDepth) + ".exr");
    if (std::filesystem::exists(file)) return readImage(file);
    std::filesystem::create_directories(file.parent_path());
    Image reference = convergedReference(scene, 512, kDeepReferenceDepth);
    writeImage(reference, file, {});
    return reference;
}

}  // namespace whitted::bench
