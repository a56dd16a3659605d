// The tables under the Trade-off dock's plot: one row per render compared with
// the pinned image, one per Measure point. Numeric columns sort by value.
#pragma once

#include <vector>

#include "tradeoff_dock/tradeoff_points.h"

class QTableWidget;

namespace whitted::ui {

QTableWidget* makePinnedTable();
QTableWidget* makeMeasureTable();

// The width that shows every column of `table` whole, frame and scroll bar included.
int tableContentWidth(const QTableWidget* table);

// Replace every row with the points' (newest pinned first; Measure in grid order).
void fillPinnedTable(QTableWidget* table, const std::vector<PinnedPoint>& points);
void fillMeasureTable(QTableWidget* table, const std::vector<TradeoffPoint>& points);

}  // namespace whitted::ui
