// Image files by name: which format an extension means, and the file of an
// animation's frame. image_io.h reads and writes them.
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

namespace whitted {

enum class ImageFormat { Png, Jpeg, Tiff, Exr, Hdr };

struct ImageFormatInfo {
    ImageFormat format;
    std::string_view name;        // for menus and messages
    std::string_view extensions;  // space-separated, lower case, with the dot
    bool isFloat;                 // linear float pixels; otherwise 8-bit sRGB
};

// PNG and JPEG: 8-bit sRGB. TIFF and OpenEXR: 32-bit float. Radiance HDR: RGBE.
const std::vector<ImageFormatInfo>& imageFormats();

// The format for a file name's extension (case-insensitive), or nothing.
std::optional<ImageFormatInfo> imageFormatFor(const std::filesystem::path& file);

// The file of frame `frame` of an animation: out.0007.png for frame 7 of
// out.png; frame 0 is a still, the file itself.
std::filesystem::path frameFile(const std::filesystem::path& file, int frame);

}  // namespace whitted
