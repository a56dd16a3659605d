#include "ranges.h"

#include <algorithm>

namespace whitted::numerics {

double allowedFractionOverOne(Precision p) {
    return p == Precision::Float ? 1e-3 : 1e-4;
}

bool meetsBound(const PointResult& r) {
    if (r.refused) return false;
    if (r.point.kind == SweepKind::Scale2) return r.bitIdentical.value_or(false);
    return r.nonFinite == 0 && r.fractionOverOne() <= allowedFractionOverOne(r.point.precision);
}

std::string boundText(SweepKind kind, Precision p) {
    if (kind == SweepKind::Scale2) return "bit-identical to the unscaled render";
    return p == Precision::Float ? "≥ 99.9% of pixels within 1/255, no NaN/Inf"
                                 : "≥ 99.99% of pixels within 1/255, no NaN/Inf";
}

namespace {

RangeSummary summarise(SweepKind kind, Precision precision, std::vector<const PointResult*> pts) {
    std::sort(pts.begin(), pts.end(),
              [](const PointResult* a, const PointResult* b) { return a->point.k < b->point.k; });
    RangeSummary s{kind, precision, pts.front()->point.k, pts.back()->point.k, {}, {}, {}, {}};
    const auto zero =
        std::find_if(pts.begin(), pts.end(), [](const PointResult* r) { return r->point.k == 0; });
    if (zero == pts.end()) return s;
    if (!meetsBound(**zero)) {
        s.failBelow = s.failAbove = 0;
        return s;
    }
    auto up = zero;
    while (up + 1 != pts.end() && meetsBound(**(up + 1))) ++up;
    auto down = zero;
    while (down != pts.begin() && meetsBound(**(down - 1))) --down;
    s.low = (*down)->point.k;
    s.high = (*up)->point.k;
    if (up + 1 != pts.end()) s.failAbove = (*(up + 1))->point.k;
    if (down != pts.begin()) s.failBelow = (*(down - 1))->point.k;
    return s;
}

}  // namespace

std::vector<RangeSummary> summariseRanges(const std::vector<PointResult>& results) {
    std::vector<RangeSummary> out;
    for (SweepKind kind : kSweepKinds)
        for (Precision precision : {Precision::Float, Precision::Double}) {
            std::vector<const PointResult*> pts;
            for (const PointResult& r : results)
                if (r.point.kind == kind && r.point.precision == precision) pts.push_back(&r);
            if (!pts.empty()) out.push_back(summarise(kind, precision, std::move(pts)));
        }
    return out;
}

}  // namespace whitted::numerics
