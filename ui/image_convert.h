// The boundary between core's linear float image and Qt: 8-bit sRGB (SPEC §5),
// through core's own srgbEncode8, so the view shows what a PNG export holds.
#pragma once

#include <QImage>

#include "image.h"

namespace whitted::ui {

// Converts the rectangle [x, x+w) x [y, y+h) of `image` into the same pixels of
// `out` (Format_RGB32, the image's size).
void convertRegion(const Image& image, QImage& out, int x, int y, int w, int h);

// The whole image as a new QImage.
QImage toQImage(const Image& image);

}  // namespace whitted::ui
