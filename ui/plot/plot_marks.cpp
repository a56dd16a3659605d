#include "plot/plot_marks.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPolygonF>

#include <algorithm>
#include <cmath>
#include <vector>

#include "plot/plot_style.h"

namespace whitted::ui::plot_painting {

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

void drawPoint(QPainter& p, QPointF c, double r, MarkerShape shape, QColor colour) {
    QColor fill = colour;
    fill.setAlpha(215);
    p.setPen(QPen(colour.darker(150), 0.8));
    p.setBrush(fill);
    drawMarker(p, c, r, shape);
}

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

}  // namespace whitted::ui::plot_painting
