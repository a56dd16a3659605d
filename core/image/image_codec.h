// The boundary between the core and OpenImageIO. OpenImageIO's 260 shared
// libraries take 0.2 s of a process's start to bind (0.4 s under ASan), which
// the editor until it exports, the farm and most tests never need; so the one
// file that calls it (image/oiio_codec.cpp) is a plug-in, whitted_oiio.so,
// which image_io.cpp loads the first time an image other than an OpenEXR of
// RGB is read, or one other than PNG and OpenEXR is written (these with their
// own libraries, png_encode.h, exr_codec.h). Only standard types cross: the
// plug-in is built with the program that loads it.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace whitted {

// One metadata attribute of a file as OpenImageIO gives it: formats that keep
// text only (PNG) hold numbers as text, so the number is what its text says.
struct CodecAttribute {
    std::string text;
    std::optional<int> integer;
    std::optional<float> real;
};

// A picture as a file holds it: `channels` values a pixel, 8-bit codes or
// floats, its pixels the window x, y, width, height of a display window
// fullWidth x fullHeight (an OpenEXR part of a farm's render).
struct CodecPicture {
    int width = 0, height = 0, channels = 3;
    bool eightBit = false;
    int x = 0, y = 0, fullWidth = 0, fullHeight = 0;
    // What decode() read: 8-bit codes when eightBit, else floats. encode() is
    // given its pixels apart, so that a float image is not copied to be written.
    std::vector<std::uint8_t> codes;
    std::vector<float> values;
    std::map<std::string, CodecAttribute> attributes;
};

struct ImageCodec {
    // Encodes `picture` (3 channels; `pixels` its 8-bit codes when eightBit,
    // else its floats) in memory, in the format of the file name's extension.
    // Returns OpenImageIO's reason, or "" when it succeeded.
    std::string (*encode)(const std::string& fileName, const CodecPicture& picture,
                          const void* pixels, std::vector<unsigned char>& encoded);
    // Reads a file's first image whole. Returns the reason it could not, or "".
    std::string (*decode)(const std::string& fileName, CodecPicture& picture);
    int (*version)();  // 20407 for OpenImageIO 2.4.7
};

}  // namespace whitted

// The plug-in's one entry point, looked up by name.
extern "C" const whitted::ImageCodec* whitted_image_codec();
