// What the command-line programs check first, and how they say what is wrong:
// "<program>: <message>" on stderr, in core's words.
#pragma once

#include <iostream>
#include <optional>
#include <string>
#include <string_view>

#include "image/image_files.h"
#include "scene/scene_io.h"

namespace whitted {

// The output file's format, or nothing, having said why.
inline std::optional<ImageFormatInfo> outputFormatOrSay(std::string_view program,
                                                        const std::string& output) {
    const auto format = imageFormatFor(output);
    if (!format)
        std::cerr << program << ": " << output
                  << ": unknown image extension (use .png, .jpg, .tif, .exr or .hdr)\n";
    return format;
}

// The scene file, or nothing, having said what is wrong with it (the file,
// and the JSON path and field, SPEC §6).
inline std::optional<Scene> sceneOrSay(std::string_view program, const std::string& file) {
    try {
        return loadScene(file);
    } catch (const SceneError& e) {
        std::cerr << program << ": " << e.what() << "\n";
        return std::nullopt;
    }
}

}  // namespace whitted
