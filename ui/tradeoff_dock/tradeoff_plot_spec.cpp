#include "tradeoff_dock/tradeoff_plot_spec.h"

#include <QObject>

#include <algorithm>

namespace whitted::ui {

namespace {

// Okabe-Ito: blue, sky blue, green and pink for Measure's scales (1, 0.5,
// 0.25, others), orange for the pinned comparisons.
const QColor kPinnedColour(0xE6, 0x9F, 0x00);
const QColor kMeasureColours[] = {QColor(0x00, 0x72, 0xB2), QColor(0x56, 0xB4, 0xE9),
                                  QColor(0x00, 0x9E, 0x73), QColor(0xCC, 0x79, 0xA7)};

// By the scale itself, so that a colour keeps its meaning while Measure's
// points come in.
QColor measureColour(double scale) {
    if (scale == 1.0) return kMeasureColours[0];
    if (scale == 0.5) return kMeasureColours[1];
    if (scale == 0.25) return kMeasureColours[2];
    return kMeasureColours[3];
}

int markerOf(Precision p) {
    return p == Precision::Float ? 0 : 1;
}

// The axes, markers and legend, without points.
PlotSpec emptyDockPlot() {
    PlotSpec spec;
    spec.xLabel = QObject::tr("Render time (s)");
    spec.yLabel = QObject::tr("RMSE, 8-bit sRGB");
    spec.logX = spec.logY = true;
    spec.markers = {{QObject::tr("float"), MarkerShape::Circle},
                    {QObject::tr("double"), MarkerShape::Square}};
    spec.highlightName = QObject::tr("Pareto front (Measure)");
    spec.showLabels = true;
    // Beside the plot: inside, it would hide the fast, noisy corner of the data.
    spec.legend = LegendPlacement::Right;
    return spec;
}

// The resolution scales Measure used, largest first: a series each.
std::vector<double> scalesOf(const std::vector<TradeoffPoint>& measure) {
    std::vector<double> scales;
    for (const TradeoffPoint& p : measure)
        if (std::find(scales.begin(), scales.end(), p.settings.resolutionScale) == scales.end())
            scales.push_back(p.settings.resolutionScale);
    std::sort(scales.rbegin(), scales.rend());
    return scales;
}

// Measure's Pareto front, joined in order of time.
PlotLine frontLine(std::vector<const TradeoffPoint*> front) {
    std::sort(front.begin(), front.end(), [](auto* a, auto* b) { return a->seconds < b->seconds; });
    PlotLine line;
    line.colour = QColor(60, 60, 60);
    line.width = 1.0;
    for (const TradeoffPoint* p : front) line.points.emplace_back(p->seconds, p->error.rmseSrgb8);
    return line;
}

}  // namespace

DockPlot dockPlot(const std::vector<PinnedPoint>& pinned,
                  const std::vector<TradeoffPoint>& measure) {
    DockPlot plot;
    PlotSpec& spec = plot.spec = emptyDockPlot();
    const std::vector<double> scales = scalesOf(measure);
    for (std::size_t i = 0; i < scales.size(); ++i)
        spec.series.push_back(
            {QObject::tr("Measure, %1 % size").arg(scales[i] * 100), measureColour(scales[i])});
    const int pinnedSeries = int(spec.series.size());
    if (!pinned.empty())
        spec.series.push_back({QObject::tr("Against the pinned image"), kPinnedColour});

    auto add = [&](double x, double y, PlotPoint point, QString tooltip) {
        if (y <= 0) {
            ++plot.identical;
            return;
        }
        point.x = x;
        point.y = y;
        spec.points.push_back(std::move(point));
        plot.tooltips.push_back(std::move(tooltip));
    };
    std::vector<const TradeoffPoint*> front;
    for (const TradeoffPoint& p : measure) {
        const int series = int(std::find(scales.begin(), scales.end(), p.settings.resolutionScale) -
                               scales.begin());
        // Labels only at full size: the front is dense, and the colour tells the scale.
        const QString label = p.settings.resolutionScale == 1.0 ? shortLabel(p) : QString();
        add(p.seconds, p.error.rmseSrgb8,
            PlotPoint{0, 0, label, p.pareto, series, markerOf(p.settings.precision)},
            pointTooltip(p));
        if (p.pareto && p.error.rmseSrgb8 > 0) front.push_back(&p);
    }
    if (front.size() > 1) spec.lines.push_back(frontLine(front));
    // The pinned comparisons joined in order of time: a handful of points
    // among Measure's hundreds would otherwise be hard to find.
    PlotLine pinnedLine;
    pinnedLine.colour = kPinnedColour;
    pinnedLine.width = 2.0;
    for (const PinnedPoint& p : pinned)
        if (p.error) {
            add(p.seconds, p.error->rmseSrgb8,
                PlotPoint{0, 0, shortLabel(p), false, pinnedSeries, markerOf(p.settings.precision)},
                pointTooltip(p));
            if (p.error->rmseSrgb8 > 0)
                pinnedLine.points.emplace_back(p.seconds, p.error->rmseSrgb8);
        }
    std::sort(pinnedLine.points.begin(), pinnedLine.points.end(),
              [](const QPointF& a, const QPointF& b) { return a.x() < b.x(); });
    if (pinnedLine.points.size() > 1) spec.lines.push_back(std::move(pinnedLine));
    return plot;
}

}  // namespace whitted::ui
