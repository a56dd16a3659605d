#include "image/image_files.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <sstream>
#include <string>

namespace whitted {
namespace fs = std::filesystem;

const std::vector<ImageFormatInfo>& imageFormats() {
    static const std::vector<ImageFormatInfo> formats = {
        {ImageFormat::Png, "PNG", ".png", false},
        {ImageFormat::Jpeg, "JPEG", ".jpg .jpeg", false},
        {ImageFormat::Tiff, "TIFF (32-bit float)", ".tif .tiff", true},
        {ImageFormat::Exr, "OpenEXR", ".exr", true},
        {ImageFormat::Hdr, "Radiance HDR", ".hdr", true},
    };
    return formats;
}

std::optional<ImageFormatInfo> imageFormatFor(const fs::path& file) {
    std::string ext = file.extension().string();
    if (ext.empty()) return std::nullopt;
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const ImageFormatInfo& f : imageFormats()) {
        std::istringstream list{std::string(f.extensions)};
        for (std::string e; list >> e;)
            if (e == ext) return f;
    }
    return std::nullopt;
}

fs::path frameFile(const fs::path& file, int frame) {
    if (frame == 0) return file;
    char number[16];
    std::snprintf(number, sizeof number, ".%04d", frame);
    fs::path named = file;
    named.replace_filename(file.stem().string() + number + file.extension().string());
    return named;
}

}  // namespace whitted
