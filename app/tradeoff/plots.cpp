#include "plots.h"

#include <algorithm>
#include <cmath>

namespace whitted::tradeoff {

namespace {

// Identical renders have an RMSE of 0, which a log axis cannot show: they sit
// at a floor a little below the smallest real error.
double plottable(double rmse, double floor) {
    return rmse > 0 ? rmse : floor;
}

double errorFloor(const std::vector<double>& errors) {
    double smallest = INFINITY;
    for (double e : errors)
        if (e > 0) smallest = std::min(smallest, e);
    return std::isfinite(smallest) ? smallest / 2 : 0.01;
}

}  // namespace

ui::PlotSpec errorAgainstTimePlot(const QString& sceneName,
                                  const std::vector<TradeoffPoint>& points) {
    ui::PlotSpec spec;
    spec.title = QStringLiteral("%1: error against render time").arg(sceneName);
    spec.xLabel = QStringLiteral("render time (s, median)");
    spec.yLabel = QStringLiteral("RMSE of the 8-bit sRGB image (codes)");
    spec.logX = spec.logY = true;
    // One series per depth measured (a grid may skip some), coloured by depth
    // on one ramp so that neighbouring depths look alike.
    int maxDepth = 0;
    std::vector<bool> measured;
    for (const TradeoffPoint& p : points) {
        maxDepth = std::max(maxDepth, p.settings.maxDepth);
        measured.resize(maxDepth + 1);
        measured[p.settings.maxDepth] = true;
    }
    for (int d = 0; d <= maxDepth; ++d)
        spec.series.push_back({measured[d] ? QStringLiteral("max depth %1").arg(d) : QString(),
                               ui::plotRampColour(maxDepth ? double(d) / maxDepth : 0.0)});
    spec.markers = {{QStringLiteral("float"), ui::MarkerShape::Circle},
                    {QStringLiteral("double"), ui::MarkerShape::Square},
                    {QStringLiteral("float, reduced size"), ui::MarkerShape::Triangle},
                    {QStringLiteral("double, reduced size"), ui::MarkerShape::Diamond}};
    std::vector<double> errors;
    for (const TradeoffPoint& p : points) errors.push_back(p.error.rmseSrgb8);
    const double floor = errorFloor(errors);
    std::vector<const TradeoffPoint*> front;
    for (const TradeoffPoint& p : points) {
        const bool reduced = p.settings.resolutionScale < 1.0;
        const int marker = (p.settings.precision == Precision::Double ? 1 : 0) + (reduced ? 2 : 0);
        ui::PlotPoint point;
        point.x = std::max(p.seconds, 1e-6);
        point.y = plottable(p.error.rmseSrgb8, floor);
        point.series = p.settings.maxDepth;
        point.marker = marker;
        point.highlighted = p.pareto;
        spec.points.push_back(point);
        if (p.pareto) front.push_back(&p);
    }
    std::sort(front.begin(), front.end(), [](const TradeoffPoint* a, const TradeoffPoint* b) {
        return a->seconds < b->seconds;
    });
    // Along the front the samples rise in runs (other settings change between
    // them): labelling only where they change keeps the labels apart.
    for (std::size_t i = 0; i < front.size(); ++i) {
        if (i > 0 && front[i]->settings.samplesPerPixel == front[i - 1]->settings.samplesPerPixel)
            continue;
        spec.points[front[i] - points.data()].label =
            QStringLiteral("%1 spp").arg(front[i]->settings.samplesPerPixel);
    }
    ui::PlotLine line;
    line.name = QStringLiteral("Pareto front");
    line.colour = Qt::black;
    for (const TradeoffPoint* p : front)
        line.points.emplace_back(std::max(p->seconds, 1e-6), plottable(p->error.rmseSrgb8, floor));
    spec.lines.push_back(line);
    spec.highlightName.clear();  // the line's legend entry names the front
    spec.showLabels = true;
    return spec;
}

ui::PlotSpec progressivePlot(const QString& sceneName,
                             const std::vector<ProgressiveSample>& curve) {
    ui::PlotSpec spec;
    spec.title = QStringLiteral("%1: progressive refinement").arg(sceneName);
    spec.xLabel = QStringLiteral("elapsed time (s)");
    spec.yLabel = QStringLiteral("RMSE of the 8-bit sRGB image (codes)");
    spec.logX = spec.logY = true;
    spec.legend = ui::LegendPlacement::None;
    std::vector<double> errors;
    for (const ProgressiveSample& s : curve) errors.push_back(s.error.rmseSrgb8);
    const double floor = errorFloor(errors);
    ui::PlotLine line;
    line.colour = ui::plotPaletteColour(0);
    line.markers = true;
    for (const ProgressiveSample& s : curve) {
        const double x = std::max(s.seconds, 1e-6), y = plottable(s.error.rmseSrgb8, floor);
        line.points.emplace_back(x, y);
        ui::PlotPoint point{
            x,
            y,
            s.samples ? QStringLiteral("%1 spp").arg(s.samples) : QStringLiteral("preview"),
            true,
            0,
            0};
        spec.points.push_back(point);
    }
    spec.series = {{QStringLiteral("pass"), ui::plotPaletteColour(0)}};
    spec.lines.push_back(line);
    spec.highlightName.clear();
    spec.highlightColour = ui::plotPaletteColour(0);
    spec.showLabels = true;
    return spec;
}

}  // namespace whitted::tradeoff
