// The frame of a plot (scatter_plot.cpp): grid lines, the axes with their
// ticks and labels, the axes' titles. Internal to the plot's painting.
#pragma once

#include "plot/scatter_plot.h"

class QFontMetricsF;
class QPainter;

namespace whitted::ui::plot_painting {

void drawGridAndAxes(QPainter& p, const PlotLayout& l, const PlotSpec& spec,
                     const QFontMetricsF& fm);

}  // namespace whitted::ui::plot_painting
