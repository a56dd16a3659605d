#include "render_quality.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "plan_file.h"

namespace whitted {

// What a render to a quality chose and reached, for --stats: the plan's
// fields as its file has them, then what the render reached, then why.
nlohmann::ordered_json qualityJson(const QualityPlan& plan, const AdaptiveOutcome& outcome) {
    nlohmann::ordered_json q = planJson(plan);
    q.erase("why");
    q["samples_per_pixel_mean"] = outcome.meanSamples;
    q["samples_per_pixel_fewest"] = outcome.fewestSamples;
    q["samples_per_pixel_most"] = outcome.mostSamples;
    q["estimated_psnr_db"] = estimatedPsnr(plan, outcome);
    q["estimated_max_error_codes"] = std::max(plan.depthLargest, outcome.estimatedLargest);
    q["tiles"] = outcome.tiles;
    q["tiles_at_sample_limit"] = outcome.tilesAtCap;
    q["why"] = plan.why;
    return q;
}

// What the plan chose and why, then what the render reached.
void sayQualityPlan(const QualityPlan& plan) {
    std::fprintf(stderr, "quality %s\n", describeTarget(plan.target).c_str());
    std::istringstream lines(plan.why);
    for (std::string line; std::getline(lines, line);) std::fprintf(stderr, "  %s\n", line.c_str());
}

void sayQualityReached(const QualityPlan& plan, const AdaptiveOutcome& a) {
    std::fprintf(stderr, "  reached: %s\n", describeReached(plan, a).c_str());
    if (a.tilesAtCap > 0)
        std::fprintf(stderr,
                     "  %d of %d tiles stopped at %d samples a pixel before reaching the target "
                     "(raise --spp)\n",
                     a.tilesAtCap, a.tiles, plan.sampling.maxSamples);
}

}  // namespace whitted
