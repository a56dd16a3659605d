// The trade-off and progressive plots of one scene, as PlotSpecs for
// ui/plot/scatter_plot.h (drawn offscreen by whitted-tradeoff).
#pragma once

#include <QString>

#include <vector>

#include "analysis/tradeoff.h"
#include "plot/scatter_plot.h"

namespace whitted::tradeoff {

// 8-bit RMSE against seconds, both log: colour by max_depth, shape by
// precision, hollow markers for scales below 1, the Pareto front as a line.
ui::PlotSpec errorAgainstTimePlot(const QString& sceneName,
                                  const std::vector<TradeoffPoint>& points);

// 8-bit RMSE against elapsed seconds at the end of every progressive pass.
ui::PlotSpec progressivePlot(const QString& sceneName, const std::vector<ProgressiveSample>& curve);

}  // namespace whitted::tradeoff
