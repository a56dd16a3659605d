// whitted-tradeoff's terminal output while the grid runs: a bar redrawn in
// place on a terminal (one line per point otherwise), with an ETA, and the
// estimate of the whole run printed before it starts.
#pragma once

#include <chrono>

#include "analysis/tradeoff.h"

namespace whitted::tradeoff {

// Relative cost of rendering a grid point once: samples times pixels. Depth and
// precision are left out; they change the cost by a factor of two or three at
// most, while samples and scale span three orders of magnitude.
double pointWork(const TradeoffSettings& settings);

// The grid's wall time, estimated from the reference render's speed, with each
// point run as TradeoffGrid's rules would. The reference is double at the
// deepest depth, so each render is estimated on the slow side, but fixed costs
// (preparing the scene, starting threads, measuring the error) are left out:
// on the seed the two about cancel (4.4 min estimated, 5.0 min taken at 640x480).
double estimateGridSeconds(const TradeoffGrid& grid, const ReferenceRender& reference);

class Progress {
  public:
    // `tty`: redraw one line in place; otherwise print a line per point.
    Progress(const TradeoffGrid& grid, bool tty);
    void point(const TradeoffProgress& p);

  private:
    bool tty_;
    double totalWork_ = 0.0, doneWork_ = 0.0;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace whitted::tradeoff
