#include "image/image_parts.h"

#include <algorithm>
#include <stdexcept>

namespace whitted {

namespace {

std::string sizeOf(int width, int height) {
    return std::to_string(width) + "x" + std::to_string(height);
}

// Each part's size and window against the first's picture.
void checkParts(const std::vector<ImagePart>& parts, const std::vector<std::string>& names) {
    if (parts.empty()) throw std::invalid_argument("no parts to merge");
    const int width = parts[0].fullWidth, height = parts[0].fullHeight;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const ImagePart& p = parts[i];
        if (p.fullWidth != width || p.fullHeight != height)
            throw std::invalid_argument(names[i] + ": a part of a " +
                                        sizeOf(p.fullWidth, p.fullHeight) + " picture, not of " +
                                        sizeOf(width, height) + " as " + names[0]);
        const PixelRect& w = p.window;
        if (!insidePicture(w, width, height) || p.image.width != w.width ||
            p.image.height != w.height)
            throw std::invalid_argument(names[i] + ": its window " + cornersText(w) +
                                        " is not inside its " + sizeOf(width, height) + " picture");
    }
}

}  // namespace

Image cropImage(const Image& image, const PixelRect& window) {
    Image out(window.width, window.height);
    for (int y = 0; y < window.height; ++y)
        std::copy_n(image.pixel(window.x, window.y + y), 3 * window.width, out.pixel(0, y));
    return out;
}

Image mergeParts(const std::vector<ImagePart>& parts, const std::vector<std::string>& names) {
    checkParts(parts, names);
    const int width = parts[0].fullWidth, height = parts[0].fullHeight;
    Image whole(width, height);
    std::vector<int> owner(std::size_t(width) * height, -1);  // the part each pixel came from
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const PixelRect& w = parts[i].window;
        for (int y = w.y; y < w.y + w.height; ++y) {
            for (int x = w.x; x < w.x + w.width; ++x) {
                int& o = owner[std::size_t(y) * width + x];
                if (o >= 0)
                    throw std::invalid_argument(names[i] + " and " + names[o] +
                                                " overlap at pixel (" + std::to_string(x) + ", " +
                                                std::to_string(y) + ")");
                o = static_cast<int>(i);
            }
            std::copy_n(parts[i].image.pixel(0, y - w.y), 3 * w.width, whole.pixel(w.x, y));
        }
    }
    const auto gap = std::find(owner.begin(), owner.end(), -1);
    if (gap != owner.end()) {
        const std::size_t at = std::size_t(gap - owner.begin());
        throw std::invalid_argument("pixel (" + std::to_string(at % width) + ", " +
                                    std::to_string(at / width) + ") of the " +
                                    sizeOf(width, height) + " picture is in no part");
    }
    return whole;
}

}  // namespace whitted
