#include "plot/plot_legend.h"

#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>
#include <vector>

#include "plot/plot_marks.h"
#include "plot/plot_style.h"

namespace whitted::ui::plot_painting {

namespace {

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

double legendRowHeight(const QFontMetricsF& fm) {
    return fm.height() * 1.3;
}
double legendSwatchWidth(const QFontMetricsF& fm) {
    return fm.height() * 1.8;
}

}  // namespace

QSizeF legendSize(const PlotSpec& spec, const QFontMetricsF& fm) {
    const std::vector<LegendEntry> entries = legendEntries(spec);
    if (entries.empty()) return {};
    double textWidth = 0.0;
    for (const LegendEntry& e : entries)
        textWidth = std::max(textWidth, fm.horizontalAdvance(e.text));
    const double pad = fm.height() * 0.4;
    return {pad + legendSwatchWidth(fm) + pad + textWidth + pad,
            pad + legendRowHeight(fm) * entries.size() + pad};
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

}  // namespace whitted::ui::plot_painting
