// The boundary between core's linear float image and Qt: 8-bit sRGB (SPEC §5),
// through core's own srgbEncode8, so the view shows what a PNG export holds.
#pragma once

#include <QColor>
#include <QImage>

#include "image/image.h"
#include "scene/scene.h"

namespace whitted::ui {

// Converts the rectangle [x, x+w) x [y, y+h) of `image` into the same pixels of
// `out` (Format_RGB32, the image's size).
void convertRegion(const Image& image, QImage& out, int x, int y, int w, int h);

// A width x height picture of `blocks`, each of whose pixels covers `block` x
// `block` pixels of it (the render's preview, one pixel per block).
QImage blocksEnlarged(const QImage& blocks, int block, int width, int height);

// A width x height picture, all black (Format_RGB32).
QImage blackImage(int width, int height);

// The whole image as a new QImage.
QImage toQImage(const Image& image);

// A linear colour as the screen shows it: each channel through the sRGB curve
// (a colour button's swatch, a ray's share of a pixel).
QColor displayColour(const Vec3& linear);

}  // namespace whitted::ui
