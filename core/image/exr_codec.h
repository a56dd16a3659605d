// OpenEXR files made and read with the OpenEXR library itself rather than
// through the OpenImageIO plug-in (image_codec.h), for the reason png_encode.h
// gives: the farm's region tasks and renders to a quality write OpenEXR, its
// merge jobs read them, and binding OpenImageIO's libraries took 0.2 s of
// every such process.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "image/image_codec.h"

namespace whitted {

// Encodes `picture` (3 channels of floats, `values` its pixels, row by row) as
// the file OpenImageIO writes for it: scanlines of R, G and B in 32-bit float,
// ZIP compression, its data window at (x, y) of a display window fullWidth x
// fullHeight, and its attributes as string, int or float attributes
// (ImageDescription named comments, as OpenEXR names it; oiio:ColorSpace left
// out, OpenEXR being linear). Returns OpenEXR's reason, or "" when it
// succeeded.
std::string encodeExr(const CodecPicture& picture, const float* values,
                      std::vector<unsigned char>& encoded);

// Reads an OpenEXR file's R, G and B channels as floats (3 channels a pixel),
// its data window placed in its display window, and its attributes as
// OpenImageIO gives them (comments named ImageDescription). Returns nullopt
// for anything else, a file OpenEXR cannot open or without those channels
// among them, which the plug-in reads or refuses in its own words.
std::optional<CodecPicture> decodeExr(const std::string& fileName);

}  // namespace whitted
