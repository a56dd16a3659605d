#include "plot/scatter_plot.h"

#include <QFontMetricsF>
#include <QGuiApplication>
#include <QPainter>
#include <QPolygonF>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace whitted::ui {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// The highlight ring's width beyond the marker, in pixels.
constexpr double kRingWidth = 2.5;

const QColor kGridMajor(210, 210, 210);
const QColor kGridMinor(236, 236, 236);
const QColor kText(30, 30, 30);
const QColor kLegendMarker(110, 110, 110);

QFont scaledFont(QFont font, double factor) {
    if (font.pixelSize() > 0)
        font.setPixelSize(std::max(1, static_cast<int>(std::lround(font.pixelSize() * factor))));
    else
        font.setPointSizeF(font.pointSizeF() * factor);
    return font;
}

QFont titleFont(const QFont& font) {
    QFont f = scaledFont(font, 1.15);
    f.setBold(true);
    return f;
}

QColor seriesColour(const PlotSpec& spec, int series) {
    if (series >= 0 && series < static_cast<int>(spec.series.size()) &&
        spec.series[series].colour.isValid())
        return spec.series[series].colour;
    return plotPaletteColour(series);
}

MarkerShape markerShape(const PlotSpec& spec, int marker) {
    if (marker >= 0 && marker < static_cast<int>(spec.markers.size()))
        return spec.markers[marker].shape;
    return MarkerShape::Circle;
}

bool anyHighlighted(const PlotSpec& spec) {
    return std::any_of(spec.points.begin(), spec.points.end(),
                       [](const PlotPoint& p) { return p.highlighted; });
}

// One row of the legend, in the order drawn: series, marker shapes, the
// highlight, named lines.
struct LegendEntry {
    enum Kind { Series, Marker, Highlight, Line } kind;
    int index;
    QString text;
};

std::vector<LegendEntry> legendEntries(const PlotSpec& spec) {
    std::vector<LegendEntry> entries;
    if (spec.legend == LegendPlacement::None) return entries;
    for (int i = 0; i < static_cast<int>(spec.series.size()); ++i)
        if (!spec.series[i].name.isEmpty())
            entries.push_back({LegendEntry::Series, i, spec.series[i].name});
    for (int i = 0; i < static_cast<int>(spec.markers.size()); ++i)
        if (!spec.markers[i].name.isEmpty())
            entries.push_back({LegendEntry::Marker, i, spec.markers[i].name});
    if (!spec.highlightName.isEmpty() && anyHighlighted(spec))
        entries.push_back({LegendEntry::Highlight, 0, spec.highlightName});
    for (int i = 0; i < static_cast<int>(spec.lines.size()); ++i)
        if (!spec.lines[i].name.isEmpty())
            entries.push_back({LegendEntry::Line, i, spec.lines[i].name});
    return entries;
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

double legendRowHeight(const QFontMetricsF& fm) {
    return fm.height() * 1.3;
}
double legendSwatchWidth(const QFontMetricsF& fm) {
    return fm.height() * 1.8;
}

QSizeF legendSize(const std::vector<LegendEntry>& entries, const QFontMetricsF& fm) {
    if (entries.empty()) return {};
    double textWidth = 0.0;
    for (const LegendEntry& e : entries)
        textWidth = std::max(textWidth, fm.horizontalAdvance(e.text));
    const double pad = fm.height() * 0.4;
    return {pad + legendSwatchWidth(fm) + pad + textWidth + pad,
            pad + legendRowHeight(fm) * entries.size() + pad};
}

void drawMarker(QPainter& p, QPointF c, double r, MarkerShape shape) {
    switch (shape) {
        case MarkerShape::Circle:
            p.drawEllipse(c, r, r);
            break;
        case MarkerShape::Square: {
            const double h = r * 0.9;
            p.drawRect(QRectF(c.x() - h, c.y() - h, 2 * h, 2 * h));
            break;
        }
        case MarkerShape::Triangle: {
            const double h = r * 1.25;
            p.drawPolygon(QPolygonF({QPointF(c.x(), c.y() - h), QPointF(c.x() + h, c.y() + h * 0.8),
                                     QPointF(c.x() - h, c.y() + h * 0.8)}));
            break;
        }
        case MarkerShape::Diamond: {
            const double h = r * 1.3;
            p.drawPolygon(QPolygonF({QPointF(c.x(), c.y() - h), QPointF(c.x() + h, c.y()),
                                     QPointF(c.x(), c.y() + h), QPointF(c.x() - h, c.y())}));
            break;
        }
    }
}

// An ordinary point: slightly translucent so that piles of points show their
// density, with a darker rim so that neighbours stay apart.
void drawPoint(QPainter& p, QPointF c, double r, MarkerShape shape, QColor colour) {
    QColor fill = colour;
    fill.setAlpha(215);
    p.setPen(QPen(colour.darker(150), 0.8));
    p.setBrush(fill);
    drawMarker(p, c, r, shape);
}

// A highlighted point: an opaque disc of the highlight colour under the opaque
// marker, so the ring reads the same around every shape and colour.
void drawHighlightedPoint(QPainter& p, QPointF c, double r, MarkerShape shape, QColor colour,
                          QColor highlight) {
    p.setPen(Qt::NoPen);
    p.setBrush(highlight);
    const double ring = r * (shape == MarkerShape::Circle ? 1.0 : 1.3) + kRingWidth;
    p.drawEllipse(c, ring, ring);
    p.setBrush(colour);
    drawMarker(p, c, r, shape);
}

void drawLine(QPainter& p, const PlotLayout& layout, const PlotLine& line, double pointRadius) {
    QPen pen(line.colour, line.width);
    if (line.dashed) pen.setStyle(Qt::DashLine);
    pen.setCapStyle(Qt::RoundCap);
    pen.setJoinStyle(Qt::RoundJoin);
    p.setPen(pen);
    p.setBrush(Qt::NoBrush);
    // A value the axis cannot show breaks the line rather than ending it.
    QPolygonF run;
    auto flush = [&] {
        if (run.size() >= 2) p.drawPolyline(run);
        run.clear();
    };
    std::vector<QPointF> vertices;
    for (const QPointF& d : line.points) {
        const QPointF px = layout.map(d.x(), d.y());
        if (std::isnan(px.x()) || std::isnan(px.y())) {
            flush();
            continue;
        }
        run << px;
        vertices.push_back(px);
    }
    flush();
    if (!line.markers) return;
    p.setPen(Qt::NoPen);
    p.setBrush(line.colour);
    for (const QPointF& v : vertices) p.drawEllipse(v, pointRadius * 0.7, pointRadius * 0.7);
}

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

void drawLabels(QPainter& p, const PlotLayout& l, const PlotSpec& spec) {
    const QFont small = scaledFont(p.font(), 0.85);
    const QFontMetricsF fm(small);
    p.setFont(small);
    p.setPen(kText);
    // Highlighted markers are obstacles too: a label over the front hides it.
    std::vector<QRectF> taken;
    const double ring = spec.pointRadius * 1.3 + kRingWidth;
    for (const PlotPoint& pt : spec.points) {
        const QPointF c = l.map(pt.x, pt.y);
        if (pt.highlighted && !std::isnan(c.x()) && !std::isnan(c.y()))
            taken.emplace_back(c.x() - ring, c.y() - ring, 2 * ring, 2 * ring);
    }
    for (const PlotPoint& pt : spec.points) {
        if (!pt.highlighted || pt.label.isEmpty()) continue;
        const QPointF c = l.map(pt.x, pt.y);
        if (std::isnan(c.x()) || std::isnan(c.y())) continue;
        const double w = fm.horizontalAdvance(pt.label), h = fm.height();
        const double gap = spec.pointRadius + kRingWidth + 2.0;
        // Above right of the point, else above left, below right, below left; a
        // label that fits none of them is left out.
        for (const QRectF& r :
             {QRectF(c.x() + gap, c.y() - h, w, h), QRectF(c.x() - gap - w, c.y() - h, w, h),
              QRectF(c.x() + gap, c.y(), w, h), QRectF(c.x() - gap - w, c.y(), w, h)}) {
            if (!l.area.contains(r)) continue;
            if (std::any_of(taken.begin(), taken.end(),
                            [&](const QRectF& t) { return t.intersects(r); }))
                continue;
            taken.push_back(r);
            // A pale backing keeps the label readable over ordinary points,
            // which labels may cover (only the highlighted ones are avoided).
            p.fillRect(r.adjusted(-1, 0, 1, 0), QColor(255, 255, 255, 190));
            p.drawText(r, Qt::AlignLeft | Qt::AlignVCenter, pt.label);
            break;
        }
    }
}

void drawLegend(QPainter& p, const PlotLayout& l, const PlotSpec& spec, const QFontMetricsF& fm) {
    const std::vector<LegendEntry> entries = legendEntries(spec);
    if (entries.empty() || l.legend.isEmpty()) return;
    p.setPen(QPen(QColor(160, 160, 160), 1.0));
    p.setBrush(QColor(255, 255, 255, 230));
    p.drawRect(l.legend);
    const double pad = fm.height() * 0.4, row = legendRowHeight(fm);
    const double swatch = legendSwatchWidth(fm), r = spec.pointRadius;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const LegendEntry& e = entries[i];
        const double top = l.legend.top() + pad + row * i;
        const QPointF c(l.legend.left() + pad + swatch / 2, top + row / 2);
        switch (e.kind) {
            case LegendEntry::Series:
                p.setPen(Qt::NoPen);
                p.setBrush(seriesColour(spec, e.index));
                drawMarker(p, c, r * 1.2,
                           spec.markers.empty() ? MarkerShape::Circle : MarkerShape::Square);
                break;
            case LegendEntry::Marker:
                drawPoint(p, c, r * 1.2, spec.markers[e.index].shape, kLegendMarker);
                break;
            case LegendEntry::Highlight:
                drawHighlightedPoint(p, c, r, MarkerShape::Circle, Qt::white, spec.highlightColour);
                break;
            case LegendEntry::Line: {
                const PlotLine& line = spec.lines[e.index];
                QPen pen(line.colour, line.width);
                if (line.dashed) pen.setStyle(Qt::DashLine);
                p.setPen(pen);
                p.drawLine(QPointF(c.x() - swatch / 2, c.y()), QPointF(c.x() + swatch / 2, c.y()));
                if (line.markers) {
                    p.setPen(Qt::NoPen);
                    p.setBrush(line.colour);
                    p.drawEllipse(c, r * 0.7, r * 0.7);
                }
                break;
            }
        }
        p.setPen(kText);
        p.drawText(QRectF(c.x() + swatch / 2 + pad, top, l.legend.width(), row),
                   Qt::AlignLeft | Qt::AlignVCenter, e.text);
    }
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
    const QSizeF legend = legendSize(legendEntries(spec), fm);
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
