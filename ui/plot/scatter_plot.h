// Scatter-and-line plots drawn with QPainter, no widgets: whitted-tradeoff writes
// them as PNG files, and the editor paints them in its trade-off dock (error
// against the pinned reference versus time). Generic on purpose: points in
// coloured series with optional marker shapes, some of them highlighted (the
// Pareto front), polylines (the front, the progressive curve), linear or log axes.
#pragma once

#include <QColor>
#include <QFont>
#include <QImage>
#include <QPointF>
#include <QRectF>
#include <QSize>
#include <QString>

#include <cstddef>
#include <optional>
#include <vector>

#include "plot/plot_axis.h"

class QPainter;

namespace whitted::ui {

enum class MarkerShape { Circle, Square, Triangle, Diamond };

// A colour of the points; its name goes into the legend.
struct PlotSeries {
    QString name;
    QColor colour;  // invalid: plotPaletteColour(index of the series)
};

// A marker shape of the points, as a second encoding beside the colour (e.g.
// colour for depth, shape for precision); listed in the legend in grey.
struct PlotMarker {
    QString name;
    MarkerShape shape = MarkerShape::Circle;
};

struct PlotPoint {
    double x = 0.0, y = 0.0;  // data units; left out if the axis cannot show it
    QString label;            // drawn beside highlighted points when showLabels
    bool highlighted = false;
    int series = 0;  // index into PlotSpec::series (colour)
    int marker = 0;  // index into PlotSpec::markers (shape); circles if there are none
};

struct PlotLine {
    QString name;  // legend entry; empty: not in the legend
    QColor colour = Qt::black;
    std::vector<QPointF> points;  // data units, joined in this order
    double width = 1.5;           // pixels
    bool dashed = false;
    bool markers = false;  // a small dot at every vertex (e.g. each progressive pass)
};

enum class LegendPlacement { Right, InsideTopRight, None };

struct PlotSpec {
    QString title, xLabel, yLabel;
    bool logX = false, logY = false;
    // Fixed ranges; otherwise fitted to the points and lines.
    std::optional<std::pair<double, double>> xRange, yRange;
    std::vector<PlotSeries> series;
    std::vector<PlotMarker> markers;
    std::vector<PlotPoint> points;
    std::vector<PlotLine> lines;  // drawn under the points
    // Highlighted points get a ring of this colour around their marker.
    QColor highlightColour = Qt::black;
    QString highlightName = QStringLiteral("Pareto front");  // legend; empty: no entry
    bool showLabels = false;   // labels of highlighted points, skipping any that would overlap
    double pointRadius = 3.5;  // pixels
    LegendPlacement legend = LegendPlacement::Right;
};

// Where everything goes for a plot drawn in `rect` with `font`: the plotting
// area (inside the axes), the axes, the legend box. paintPlot lays out with the
// painter's font, so pass the same font to map points or hit-test for tooltips.
struct PlotLayout {
    QRectF area;
    PlotAxis x, y;
    QRectF legend;  // empty when there is none
    // The pixel of data point (x, y); NaN coordinates where an axis cannot show it.
    QPointF map(double dataX, double dataY) const;
};
PlotLayout plotLayout(const QRectF& rect, const PlotSpec& spec, const QFont& font);

// Draws the whole plot inside `rect`: white background, title, grid, axes with
// ticks and labels, lines, points (highlighted ones last, on top), legend.
void paintPlot(QPainter& painter, const QRectF& rect, const PlotSpec& spec);

// The plot as an opaque image of `size` drawn with plotFont(size), for writing
// to a file. Needs a QGuiApplication.
QImage renderPlot(const PlotSpec& spec, QSize size);
// The application's font at a pixel size scaled to the image (about 40 lines of
// text in its height), so that plotLayout can reproduce renderPlot's layout.
QFont plotFont(QSize size);

// The point of spec.points nearest to `pixel` within `radius` pixels, if any.
std::optional<std::size_t> pointNear(const PlotLayout& layout, const PlotSpec& spec, QPointF pixel,
                                     double radius);

// A colour-blind-safe qualitative palette (Okabe and Ito), cycling.
QColor plotPaletteColour(int index);
// A sequential ramp (viridis: dark purple at 0 to yellow at 1) for ordered
// series such as depths; t is clamped to [0, 1].
QColor plotRampColour(double t);

}  // namespace whitted::ui
