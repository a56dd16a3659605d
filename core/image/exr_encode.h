// OpenEXR files made with the OpenEXR library itself rather than through the
// OpenImageIO plug-in (image_codec.h), for the reason png_encode.h gives: the
// farm's region tasks and renders to a quality write OpenEXR, and binding
// OpenImageIO's libraries took 0.2 s of every such process.
#pragma once

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

}  // namespace whitted
