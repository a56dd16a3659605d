// Image files through OpenImageIO (SPEC §5): 8-bit formats get the sRGB curve
// and clamping, float formats stay linear. Writes are atomic.
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "image/image.h"
#include "image/image_files.h"
#include "image/image_metadata.h"
#include "scene/scene.h"

namespace whitted {

class ImageIoError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// Writes the image in the format of the file's extension. On any failure throws
// ImageIoError naming the file, and leaves no file (and no partial file) behind;
// an existing file of that name is only replaced once the new one is complete.
void writeImage(const Image& image, const std::filesystem::path& file,
                const ImageMetadata& metadata);

// Reads any image OpenImageIO knows as linear RGB floats (8-bit files are
// decoded from sRGB; an OpenEXR's R, G and B without OpenImageIO). Throws
// ImageIoError.
Image readImage(const std::filesystem::path& file);

// A window of a larger picture (a farm's region): `image` holds the pixels of
// `window` in a picture of fullWidth x fullHeight.
struct ImagePart {
    Image image;
    PixelRect window{0, 0, 0, 0};
    int fullWidth = 0, fullHeight = 0;
    ImageMetadata metadata;  // read back: the settings and time the file records
};

// Writes the part as OpenEXR, its data window the part's place in the full
// picture (the display window), so the file says where it belongs. As
// writeImage(), atomically; any other extension is refused (ImageIoError).
void writeImagePart(const ImagePart& part, const std::filesystem::path& file,
                    const ImageMetadata& metadata);

// readImage() with where the pixels lie: an OpenEXR's data and display windows;
// for any other file the whole picture.
ImagePart readImagePart(const std::filesystem::path& file);

// Where the image plug-in is for a process that is not one of the programs,
// whose place relative to the program finds it (the Python module, loaded by
// python3, gives its own): call before any image is read or written.
void setImageCodecPath(const std::filesystem::path& plugin);

// The version of the OpenImageIO library in use, "2.4.7" (for About boxes).
std::string openImageIOVersion();

}  // namespace whitted
