#include "precision_dock/heat_map_view.h"

#include <QPainter>

#include <algorithm>

namespace whitted::ui {

HeatMapView::HeatMapView(QWidget* parent) : QWidget(parent) {
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void HeatMapView::setImage(const QImage& image) {
    image_ = image.convertToFormat(QImage::Format_RGB32);
    reduced_ = QImage();
    update();
}

QRect HeatMapView::imageRect() const {
    if (image_.isNull()) return {};
    const QSize s = image_.size().scaled(size(), Qt::KeepAspectRatio);
    return QRect(QPoint((width() - s.width()) / 2, (height() - s.height()) / 2), s);
}

void HeatMapView::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), palette().window());
    const QRect r = imageRect();
    if (r.isEmpty()) return;
    if (r.width() >= image_.width()) {
        p.drawImage(r, image_);  // no smoothing: blocks of whole pixels
        return;
    }
    if (reduced_.size() != r.size()) reduced_ = reduceKeepingBrightest(image_, r.size());
    p.drawImage(r.topLeft(), reduced_);
}

QImage reduceKeepingBrightest(const QImage& image, QSize size) {
    const QImage in = image.convertToFormat(QImage::Format_RGB32);
    QImage out(size, QImage::Format_RGB32);
    const int w = in.width(), h = in.height();
    for (int y = 0; y < size.height(); ++y) {
        const int y0 = y * h / size.height(), y1 = std::max(y0 + 1, (y + 1) * h / size.height());
        auto* line = reinterpret_cast<QRgb*>(out.scanLine(y));
        for (int x = 0; x < size.width(); ++x) {
            const int x0 = x * w / size.width(), x1 = std::max(x0 + 1, (x + 1) * w / size.width());
            QRgb best = 0;
            int bestGray = -1;
            for (int sy = y0; sy < y1; ++sy) {
                const auto* src = reinterpret_cast<const QRgb*>(in.constScanLine(sy));
                for (int sx = x0; sx < x1; ++sx) {
                    const int g = qGray(src[sx]);
                    if (g > bestGray) {
                        bestGray = g;
                        best = src[sx];
                    }
                }
            }
            line[x] = best;
        }
    }
    return out;
}

}  // namespace whitted::ui
