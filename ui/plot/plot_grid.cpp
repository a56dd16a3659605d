#include "plot/plot_grid.h"

#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>

#include "plot/plot_style.h"

namespace whitted::ui::plot_painting {

void drawGridAndAxes(QPainter& p, const PlotLayout& l, const PlotSpec& spec,
                     const QFontMetricsF& fm) {
    const QRectF& a = l.area;
    const double tick = fm.height() * 0.3;
    auto xAt = [&](double v) { return a.left() + l.x.fraction(v) * a.width(); };
    auto yAt = [&](double v) { return a.bottom() - l.y.fraction(v) * a.height(); };

    for (int pass = 0; pass < 2; ++pass) {
        const bool major = pass == 1;
        p.setPen(QPen(major ? kGridMajor : kGridMinor, 1.0));
        for (double v : major ? l.x.major : l.x.minor)
            p.drawLine(QPointF(xAt(v), a.top()), QPointF(xAt(v), a.bottom()));
        for (double v : major ? l.y.major : l.y.minor)
            p.drawLine(QPointF(a.left(), yAt(v)), QPointF(a.right(), yAt(v)));
    }

    p.setPen(QPen(kText, 1.0));
    p.setBrush(Qt::NoBrush);
    p.drawRect(a);
    for (double v : l.x.minor)
        p.drawLine(QPointF(xAt(v), a.bottom()), QPointF(xAt(v), a.bottom() + tick * 0.6));
    for (double v : l.y.minor)
        p.drawLine(QPointF(a.left() - tick * 0.6, yAt(v)), QPointF(a.left(), yAt(v)));
    for (double v : l.x.major) {
        const double x = xAt(v);
        p.drawLine(QPointF(x, a.bottom()), QPointF(x, a.bottom() + tick));
        const QString text = l.x.label(v);
        const double w = fm.horizontalAdvance(text);
        p.drawText(QRectF(x - w, a.bottom() + tick, 2 * w, fm.height()), Qt::AlignCenter, text);
    }
    for (double v : l.y.major) {
        const double y = yAt(v);
        p.drawLine(QPointF(a.left() - tick, y), QPointF(a.left(), y));
        const QString text = l.y.label(v);
        p.drawText(QRectF(a.left() - tick - fm.height() * 0.3 - 1000.0, y - fm.height(), 1000.0,
                          2 * fm.height()),
                   Qt::AlignRight | Qt::AlignVCenter, text);
    }

    if (!spec.xLabel.isEmpty())
        p.drawText(QRectF(a.left(), a.bottom() + tick + fm.height() * 1.25, a.width(), fm.height()),
                   Qt::AlignHCenter | Qt::AlignTop, spec.xLabel);
    if (!spec.yLabel.isEmpty()) {
        double labelWidth = 0.0;
        for (double v : l.y.major)
            labelWidth = std::max(labelWidth, fm.horizontalAdvance(l.y.label(v)));
        const double centreX = a.left() - tick - fm.height() * 0.3 - labelWidth - fm.height() * 0.9;
        p.save();
        p.translate(centreX, a.center().y());
        p.rotate(-90.0);
        p.drawText(QRectF(-a.height() / 2, -fm.height() / 2, a.height(), fm.height()),
                   Qt::AlignCenter, spec.yLabel);
        p.restore();
    }
}

}  // namespace whitted::ui::plot_painting
