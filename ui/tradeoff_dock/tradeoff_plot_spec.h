// The Trade-off dock's plot: error (RMSE of the 8-bit sRGB image) against
// render time, both on log axes. Measure's points in one colour per
// resolution scale, its Pareto front ringed, joined and (at full size)
// labelled; renders compared with the pinned image in a colour of their own.
// Circles are float, squares double.
#pragma once

#include <QString>

#include <vector>

#include "plot/scatter_plot.h"
#include "tradeoff_dock/tradeoff_points.h"

namespace whitted::ui {

struct DockPlot {
    PlotSpec spec;
    std::vector<QString> tooltips;  // parallel to spec.points
    int identical = 0;              // points with error 0, which a log axis cannot show (left out)
};

DockPlot dockPlot(const std::vector<PinnedPoint>& pinned,
                  const std::vector<TradeoffPoint>& measure);

}  // namespace whitted::ui
