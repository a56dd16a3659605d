// Timing a render to a target against a fixed render, in pairs:
// shared by bench_quality and bench_quality_fields.
// Times of a few milliseconds say little alone on a shared machine: where ours
// and the fixed render together take under half a second, they are run again
// in pairs, one after the other, as many as fill about a second, and the
// medians are kept with the median of the pairs' ratios.
#pragma once

#include <algorithm>
#include <vector>

#include "analysis/quality_check.h"
#include "analysis/render_presets.h"

namespace whitted::bench {

inline double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

struct PairedTimes {
    double ours = 0.0, fixed = 0.0, ratio = 0.0;  // medians
    int pairs = 1;
};

// Ours (planning included) and the fixed render, timed in pairs until about
// `seconds` have gone, at least `fewest` and at most 15 pairs; the first pair
// is the one measured.
inline PairedTimes pairedTimes(const Scene& scene, const QualityTarget& target, const Scene& fixed,
                               const Image& reference, double oursFirst, double fixedFirst,
                               int fewest = 1, double seconds = 1.0) {
    std::vector<double> ours{oursFirst}, fixedTimes{fixedFirst}, ratios{oursFirst / fixedFirst};
    const int pairs = std::clamp(int(seconds / (oursFirst + fixedFirst)), fewest, 15);
    for (int i = 1; i < pairs; ++i) {
        ours.push_back(checkQuality(scene, target, reference).seconds);
        fixedTimes.push_back(checkFixed(fixed, reference).seconds);
        ratios.push_back(ours.back() / fixedTimes.back());
    }
    return {median(ours), median(fixedTimes), median(ratios), pairs};
}

// The scene with the preset's samples and depth.
inline Scene withPreset(Scene scene, const RenderPreset& preset) {
    scene.render.samplesPerPixel = preset.samplesPerPixel;
    scene.render.maxDepth = preset.maxDepth;
    return scene;
}

}  // namespace whitted::bench
