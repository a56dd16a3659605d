#include "viewport/image_convert.h"

#include <algorithm>

#include "image/srgb.h"

namespace whitted::ui {

void convertRegion(const Image& image, QImage& out, int x, int y, int w, int h) {
    for (int row = y; row < y + h; ++row) {
        const float* in = image.pixel(x, row);
        auto* line = reinterpret_cast<QRgb*>(out.bits() + qsizetype(row) * out.bytesPerLine()) + x;
        // Runs of equal pixels (the preview's blocks, the background) convert once.
        float last[3] = {-1.0f, -1.0f, -1.0f};
        QRgb lastRgb = 0;
        for (int i = 0; i < w; ++i, in += 3) {
            if (in[0] != last[0] || in[1] != last[1] || in[2] != last[2]) {
                last[0] = in[0], last[1] = in[1], last[2] = in[2];
                lastRgb = qRgb(srgbEncode8(in[0]), srgbEncode8(in[1]), srgbEncode8(in[2]));
            }
            line[i] = lastRgb;
        }
    }
}

QImage blocksEnlarged(const QImage& blocks, int block, int width, int height) {
    QImage out(width, height, QImage::Format_RGB32);
    for (int y = 0; y < height; ++y) {
        auto* line = reinterpret_cast<QRgb*>(out.scanLine(y));
        if (y % block != 0) {  // the row above, in the same block row
            std::copy_n(reinterpret_cast<const QRgb*>(out.constScanLine(y - 1)), width, line);
            continue;
        }
        const auto* in = reinterpret_cast<const QRgb*>(blocks.constScanLine(y / block));
        for (int x = 0; x < width; ++x) line[x] = in[x / block];
    }
    return out;
}

QImage blackImage(int width, int height) {
    QImage out(width, height, QImage::Format_RGB32);
    out.fill(Qt::black);
    return out;
}

QImage toQImage(const Image& image) {
    QImage out(image.width, image.height, QImage::Format_RGB32);
    convertRegion(image, out, 0, 0, image.width, image.height);
    return out;
}

QColor displayColour(const Vec3& linear) {
    return QColor::fromRgbF(srgbEncode(static_cast<float>(linear.x)),
                            srgbEncode(static_cast<float>(linear.y)),
                            srgbEncode(static_cast<float>(linear.z)));
}

}  // namespace whitted::ui
