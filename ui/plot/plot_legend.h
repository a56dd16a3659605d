// The legend of a plot (scatter_plot.cpp): its size, for the layout, and its
// painting. Internal to the plot's painting.
#pragma once

#include <QSizeF>

#include "plot/scatter_plot.h"

class QFontMetricsF;
class QPainter;

namespace whitted::ui::plot_painting {

// The legend's box with every entry of `spec`; empty when there are none.
QSizeF legendSize(const PlotSpec& spec, const QFontMetricsF& fm);
void drawLegend(QPainter& p, const PlotLayout& l, const PlotSpec& spec, const QFontMetricsF& fm);

}  // namespace whitted::ui::plot_painting
