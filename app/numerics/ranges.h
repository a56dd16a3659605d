// The bounds a precision must meet at each point of the sweep, and the contiguous
// range of k around 0 in which each precision meets them.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "measure.h"
#include "sweep_plan.h"

namespace whitted::numerics {

// Largest share of pixels allowed more than 1/255 from the double reference:
// 0.1% in float, 0.01% in double (the bounds for the 10^k scale sweep, applied
// to the offset sweep too).
double allowedFractionOverOne(Precision p);

// Whether a point is right: for 2^k, bit-identical to the same-precision
// reference (power-of-two scaling is exact); otherwise within the allowed
// fraction, and no NaN or infinite pixel. A refused scene never is.
bool meetsBound(const PointResult& r);

// The bound in words, for the report.
std::string boundText(SweepKind kind, Precision p);

struct RangeSummary {
    SweepKind kind;
    Precision precision;
    int testedLow = 0, testedHigh = 0;  // smallest and largest k tested
    // The contiguous run of tested k around 0 (from 0 for offsets) that all meet
    // the bound; nothing when k = 0 itself fails.
    std::optional<int> low, high;
    // The tested points next to that run, which fail; nothing if the run reaches
    // the end of the sweep on that side.
    std::optional<int> failBelow, failAbove;
};

// One summary per (kind, precision) present in `results`, in sweep order.
std::vector<RangeSummary> summariseRanges(const std::vector<PointResult>& results);

}  // namespace whitted::numerics
