// The points of the numerics sweep: the base scene scaled by
// 10^k or 2^k, or moved by (1,1,1)·10^k, each rendered in float and in double.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"

namespace whitted::numerics {

enum class SweepKind {
    Scale10,    // every length times 10^k
    Scale2,     // every length times 2^k: exact in binary, so the image must not change
    Translate,  // every position plus (1,1,1)·10^k, k >= 0
};

inline constexpr SweepKind kSweepKinds[] = {SweepKind::Scale10, SweepKind::Scale2,
                                            SweepKind::Translate};

// "scale10", "scale2", "translate": for file names and the CSV.
std::string_view sweepId(SweepKind kind);
// "scale ×10^k" and the like: for headings.
std::string_view sweepTitle(SweepKind kind);

struct SweepPoint {
    SweepKind kind = SweepKind::Scale10;
    Precision precision = Precision::Float;
    int k = 0;
};

// The transform of a point as text: "1e-4", "2^-3", "(1e5, 1e5, 1e5)".
std::string transformLabel(const SweepPoint& p);

// The base scene transformed and set to the point's precision. Scale factors are
// the correctly rounded doubles of 10^k and 2^k; offsets 10^k are whole numbers,
// hence whole multiples of the seed's checker period (2 × 0.5).
Scene sceneAt(const Scene& base, const SweepPoint& p);

// Every point, grouped by kind, then precision, then k ascending.
// full: float 10^k for k in [-20, 20] (then every 5 to ±40), double 10^k for k in
// [-40, 40] (then every 10 to ±200, past double's range); 2^k for k in [-20, 20];
// offsets 10^k for k in [0, 12] (float) and [0, 20] (double).
// quick: a handful of each, for the program's own test.
std::vector<SweepPoint> sweepPlan(bool quick);

}  // namespace whitted::numerics
