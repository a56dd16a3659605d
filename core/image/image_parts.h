// Pictures cut into windows and put back together: a farm renders each
// region of a picture as its own job (whitted-render --region) and merges
// the parts (whitted-render merge). Plain values, no Qt.
#pragma once

#include <string>
#include <vector>

#include "image/image.h"
#include "image/image_io.h"

namespace whitted {

// The pixels of `window`, which must lie inside `image`.
Image cropImage(const Image& image, const PixelRect& window);

// The whole picture from its parts. Every pixel must lie in exactly one part,
// and all parts must be of pictures of the same size; otherwise throws
// std::invalid_argument saying which part (by `names`, one a part) and how.
Image mergeParts(const std::vector<ImagePart>& parts, const std::vector<std::string>& names);

}  // namespace whitted
