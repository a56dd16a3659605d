// PNG files made with libpng itself rather than through the OpenImageIO
// plug-in (image_codec.h): a PNG is what most renders write, and binding
// OpenImageIO's libraries took 0.2 s of every such process, where the seed's
// render takes 13 ms (docs/design/performance.md). libpng is one library and
// binds in a millisecond.
#pragma once

#include <string>
#include <vector>

#include "image/image_codec.h"

namespace whitted {

// Encodes `picture` (3 channels of 8-bit sRGB codes, `codes` its pixels) as
// the file OpenImageIO writes for it: 8-bit RGB with sRGB, gAMA and cHRM
// chunks, its offset, and its text attributes as tEXt chunks (ImageDescription
// named Description, as PNG names it); attributes given as numbers are left out,
// as OpenImageIO leaves them. Returns libpng's reason, or "" when it succeeded.
std::string encodePng(const CodecPicture& picture, const void* codes,
                      std::vector<unsigned char>& encoded);

}  // namespace whitted
