// The plot's layout and the whole plot put together; its parts are painted in
// plot_grid.cpp (grid and axes), plot_marks.cpp (points, lines, labels) and
// plot_legend.cpp.
#include "plot/scatter_plot.h"

#include <QFontMetricsF>
#include <QGuiApplication>
#include <QPainter>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "plot/plot_grid.h"
#include "plot/plot_legend.h"
#include "plot/plot_marks.h"
#include "plot/plot_style.h"

namespace whitted::ui {

using namespace plot_painting;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

QFont titleFont(const QFont& font) {
    QFont f = scaledFont(font, 1.15);
    f.setBold(true);
    return f;
}

// The data range of one coordinate over points and lines, counting only values
// the axis can show (finite; positive on a log axis).
std::pair<double, double> dataRange(const PlotSpec& spec, bool xCoordinate) {
    const bool log = xCoordinate ? spec.logX : spec.logY;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    auto add = [&](double v) {
        if (!std::isfinite(v) || (log && v <= 0.0)) return;
        lo = std::min(lo, v), hi = std::max(hi, v);
    };
    for (const PlotPoint& p : spec.points) add(xCoordinate ? p.x : p.y);
    for (const PlotLine& line : spec.lines)
        for (const QPointF& p : line.points) add(xCoordinate ? p.x() : p.y());
    return {lo, hi};
}

PlotAxis axisFor(const PlotSpec& spec, bool xCoordinate) {
    const auto& fixed = xCoordinate ? spec.xRange : spec.yRange;
    const auto [lo, hi] = fixed ? *fixed : dataRange(spec, xCoordinate);
    return makePlotAxis(lo, hi, xCoordinate ? spec.logX : spec.logY);
}

}  // namespace

QPointF PlotLayout::map(double dataX, double dataY) const {
    const double fx = x.fraction(dataX), fy = y.fraction(dataY);
    return {std::isnan(fx) ? kNaN : area.left() + fx * area.width(),
            std::isnan(fy) ? kNaN : area.bottom() - fy * area.height()};
}

PlotLayout plotLayout(const QRectF& rect, const PlotSpec& spec, const QFont& font) {
    PlotLayout l;
    l.x = axisFor(spec, true);
    l.y = axisFor(spec, false);
    const QFontMetricsF fm(font);
    const double pad = fm.height() * 0.6, tick = fm.height() * 0.3;

    double top = rect.top() + pad;
    if (!spec.title.isEmpty()) top += QFontMetricsF(titleFont(font)).height() + pad * 0.5;

    double yLabelWidth = 0.0;
    for (double v : l.y.major)
        yLabelWidth = std::max(yLabelWidth, fm.horizontalAdvance(l.y.label(v)));
    double left = rect.left() + pad + yLabelWidth + fm.height() * 0.3 + tick;
    if (!spec.yLabel.isEmpty()) left += fm.height() * 1.4;

    double bottom = rect.bottom() - pad - tick - fm.height();
    if (!spec.xLabel.isEmpty()) bottom -= fm.height() * 1.4;

    // The last x tick label is centred on the right edge: keep room for its half.
    double right = rect.right() - pad;
    if (!l.x.major.empty()) right -= fm.horizontalAdvance(l.x.label(l.x.major.back())) / 2;
    const QSizeF legend = legendSize(spec, fm);
    if (spec.legend == LegendPlacement::Right && !legend.isEmpty())
        right = std::min(right, rect.right() - pad - legend.width() - pad);

    l.area = QRectF(QPointF(left, top),
                    QPointF(std::max(left + 1.0, right), std::max(top + 1.0, bottom)));
    if (!legend.isEmpty()) {
        if (spec.legend == LegendPlacement::Right)
            l.legend = QRectF(QPointF(l.area.right() + pad, l.area.top()), legend);
        else if (spec.legend == LegendPlacement::InsideTopRight)
            l.legend = QRectF(
                QPointF(l.area.right() - pad * 0.5 - legend.width(), l.area.top() + pad * 0.5),
                legend);
    }
    return l;
}

void paintPlot(QPainter& painter, const QRectF& rect, const PlotSpec& spec) {
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::TextAntialiasing);
    painter.fillRect(rect, Qt::white);
    const QFont font = painter.font();
    const QFontMetricsF fm(font);
    const PlotLayout l = plotLayout(rect, spec, font);

    if (!spec.title.isEmpty()) {
        painter.setFont(titleFont(font));
        painter.setPen(kText);
        painter.drawText(QRectF(rect.left(), rect.top() + fm.height() * 0.4, rect.width(),
                                QFontMetricsF(painter.font()).height()),
                         Qt::AlignHCenter | Qt::AlignTop, spec.title);
        painter.setFont(font);
    }
    drawGridAndAxes(painter, l, spec, fm);

    // Markers on the edge of the area may overhang it; nothing else may.
    const double overhang = spec.pointRadius * 1.3 + kRingWidth + 1.0;
    painter.setClipRect(l.area.adjusted(-overhang, -overhang, overhang, overhang));
    for (const PlotLine& line : spec.lines) drawLine(painter, l, line, spec.pointRadius);
    for (bool highlighted : {false, true}) {
        for (const PlotPoint& pt : spec.points) {
            if (pt.highlighted != highlighted) continue;
            const QPointF c = l.map(pt.x, pt.y);
            if (std::isnan(c.x()) || std::isnan(c.y())) continue;
            const QColor colour = seriesColour(spec, pt.series);
            const MarkerShape shape = markerShape(spec, pt.marker);
            if (highlighted)
                drawHighlightedPoint(painter, c, spec.pointRadius, shape, colour,
                                     spec.highlightColour);
            else
                drawPoint(painter, c, spec.pointRadius, shape, colour);
        }
    }
    if (spec.showLabels) drawLabels(painter, l, spec);
    painter.setClipping(false);
    painter.setFont(font);
    drawLegend(painter, l, spec, fm);
    painter.restore();
}

QImage renderPlot(const PlotSpec& spec, QSize size) {
    QImage image(size, QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.setFont(plotFont(size));
    paintPlot(painter, QRectF(QPointF(0, 0), QSizeF(size)), spec);
    painter.end();
    return image;
}

QFont plotFont(QSize size) {
    QFont font = QGuiApplication::font();
    // About 40 lines of text in the height (of a 4:3 part of a wide image):
    // readable when the PNG is shown at its own size or a little smaller.
    const int height = std::min(size.height(), size.width() * 3 / 4);
    font.setPixelSize(std::max(10, height / 40));
    return font;
}

std::optional<std::size_t> pointNear(const PlotLayout& layout, const PlotSpec& spec, QPointF pixel,
                                     double radius) {
    std::optional<std::size_t> best;
    double bestDistance = radius;
    for (std::size_t i = 0; i < spec.points.size(); ++i) {
        const QPointF c = layout.map(spec.points[i].x, spec.points[i].y);
        if (std::isnan(c.x()) || std::isnan(c.y())) continue;
        const double d = std::hypot(c.x() - pixel.x(), c.y() - pixel.y());
        if (d <= bestDistance) bestDistance = d, best = i;
    }
    return best;
}

QColor plotPaletteColour(int index) {
    static const std::array<QColor, 8> kPalette{QColor(0x00, 0x72, 0xB2), QColor(0xD5, 0x5E, 0x00),
                                                QColor(0x00, 0x9E, 0x73), QColor(0xE6, 0x9F, 0x00),
                                                QColor(0xCC, 0x79, 0xA7), QColor(0x56, 0xB4, 0xE9),
                                                QColor(0x00, 0x00, 0x00), QColor(0xF0, 0xE4, 0x42)};
    const int n = static_cast<int>(kPalette.size());
    return kPalette[((index % n) + n) % n];
}

QColor plotRampColour(double t) {
    static const std::array<QColor, 9> kViridis{
        QColor(0x44, 0x01, 0x54), QColor(0x47, 0x2D, 0x7B), QColor(0x3B, 0x52, 0x8B),
        QColor(0x2C, 0x72, 0x8E), QColor(0x21, 0x91, 0x8C), QColor(0x28, 0xAE, 0x80),
        QColor(0x5E, 0xC9, 0x62), QColor(0xAD, 0xDC, 0x30), QColor(0xFD, 0xE7, 0x25)};
    t = std::clamp(std::isnan(t) ? 0.0 : t, 0.0, 1.0) * (kViridis.size() - 1);
    const std::size_t i = std::min(static_cast<std::size_t>(t), kViridis.size() - 2);
    const double f = t - i;
    const QColor& a = kViridis[i];
    const QColor& b = kViridis[i + 1];
    auto mix = [f](int x, int y) { return static_cast<int>(std::lround(x + (y - x) * f)); };
    return QColor(mix(a.red(), b.red()), mix(a.green(), b.green()), mix(a.blue(), b.blue()));
}

}  // namespace whitted::ui
