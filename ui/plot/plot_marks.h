// What marks a plot's data (scatter_plot.cpp, plot_legend.cpp): markers of
// each shape, ordinary and highlighted points, polylines, and the labels of
// highlighted points. Internal to the plot's painting.
#pragma once

#include <QColor>
#include <QPointF>

#include "plot/scatter_plot.h"

class QPainter;

namespace whitted::ui::plot_painting {

QColor seriesColour(const PlotSpec& spec, int series);
MarkerShape markerShape(const PlotSpec& spec, int marker);

void drawMarker(QPainter& p, QPointF c, double r, MarkerShape shape);
// An ordinary point: slightly translucent so that piles of points show their
// density, with a darker rim so that neighbours stay apart.
void drawPoint(QPainter& p, QPointF c, double r, MarkerShape shape, QColor colour);
// A highlighted point: an opaque disc of the highlight colour under the opaque
// marker, so the ring reads the same around every shape and colour.
void drawHighlightedPoint(QPainter& p, QPointF c, double r, MarkerShape shape, QColor colour,
                          QColor highlight);
void drawLine(QPainter& p, const PlotLayout& layout, const PlotLine& line, double pointRadius);
void drawLabels(QPainter& p, const PlotLayout& l, const PlotSpec& spec);

}  // namespace whitted::ui::plot_painting
