#include "analysis/quality_why.h"

#include <algorithm>
#include <cstdio>

#include "analysis/quality_depth.h"
#include "base/printed.h"
#include "image/image_error.h"

namespace whitted {

namespace planning {

namespace {

// The picture's check looked for slivers with more samples than its centres.
std::string pictureSamplesWhy(const QualityPlan& p) {
    const int samples = pictureCheckSamples(*p.target.largestCodes, p.sampling.maxSamples);
    if (!p.depthAtPictureSize || samples == 1) return "";
    return printed(" at the centres or with %d samples a pixel", samples);
}

std::string depthWhy(const QualityPlan& p) {
    std::string why =
        "depth " + std::to_string(p.maxDepth) + (p.depthGiven ? " (given)" : "") +
        printed(", following no ray that passes on less than %g of the light", kQualityPruneWeight);
    why += p.depthAtPictureSize
               ? printed(": against depth %d, the picture's pixel centres change by ",
                         p.referenceDepth) +
                     (p.depthBoundsFrom >= 0 ? "at most " : "") +
                     printed("%.3g codes^2 on average", p.depthMse)
               : printed(": against depth %d, a %dx%d probe changes by %.3g codes^2 on average",
                         p.referenceDepth, p.probeWidth, p.probeHeight, p.depthMse);
    why += printed(" (the target allows %.3g)", allowedMse(p.target.psnrDb));
    if (p.target.largestCodes)
        why += printed(" and %.3g codes at most", p.depthLargest) + pictureSamplesWhy(p) +
               printed(" (limit %.3g)", *p.target.largestCodes) +
               (p.depthLargestSamples > 1
                    ? printed(", with %d samples a pixel of the picture where the centres "
                              "differ most",
                              p.depthLargestSamples)
                    : std::string());
    if (p.depthBoundsFrom >= 0)
        why += printed(
            "; past depth %d the check rendered only the pixels it left in doubt, "
            "so elsewhere the figures are that depth's",
            p.depthBoundsFrom);
    if (!p.depthShort) return why;
    why += "\nno depth up to " + std::to_string(kDeepestPlanned) +
           " leaves the samples their share: rays trapped in glass or between mirrors "
           "still change the picture, ";
    // No number of samples takes back what the depth cuts off: a cut over
    // the whole limit makes a miss of the largest error likely.
    if (p.target.largestCodes && p.depthLargest > *p.target.largestCodes)
        return why + printed("so a pixel is likely to be off by more than %.3g codes",
                             *p.target.largestCodes);
    return why + "so the target may be missed";
}

std::string outOfReachWhy(const QualityPlan& p, double total) {
    return std::string("\nthe ") + (p.depthGiven ? "given depth" : "deepest depth planned") +
           (p.depthMse > total ? " alone cuts" : " and float together cut") +
           " off more than the target allows: it cannot be met, so the samples aim for " +
           printed("the noise of a picture that meets it (%.3g codes^2)", p.sampling.allowedMse);
}

std::string samplingWhy(const QualityPlan& p) {
    std::string why = p.sampling.centresFirst
                          ? "samples: one at each pixel's centre, its error estimated from "
                            "neighbouring pixels; then "
                          : "samples: ";
    why += printed("each tile until the picture's estimated error is under %.3g codes^2",
                   p.sampling.allowedMse);
    if (p.target.largestCodes)
        why += printed(" and no pixel's estimate over %.3g codes", p.sampling.allowedLargest);
    return why + ", at most " + std::to_string(p.sampling.maxSamples) + " a pixel";
}

}  // namespace

std::string planWhy(const QualityPlan& plan, bool inFloat, double total) {
    std::string why = depthWhy(plan) + "\n";
    if (inFloat)
        why +=
            printed("float against double: %.3g codes^2 in the same probe", plan.precisionMse) +
            (plan.precisionSamples > 1 ? printed(", at %d samples a pixel", plan.precisionSamples)
                                       : std::string()) +
            "\n";
    why += samplingWhy(plan);
    if (plan.depthMse + plan.precisionMse > total) why += outOfReachWhy(plan, total);
    return why;
}

}  // namespace planning

std::string describeTarget(const QualityTarget& t) {
    std::string text =
        (t.name.empty() ? std::string() : t.name + ": ") + printed("%.3g dB", t.psnrDb);
    if (t.largestCodes) text += printed(", no pixel off by more than %.3g codes", *t.largestCodes);
    return text;
}

std::string describeReached(const QualityPlan& plan, const AdaptiveOutcome& a) {
    std::string text = a.fewestSamples == a.mostSamples
                           ? printed(a.mostSamples == 1 ? "%d sample a pixel everywhere"
                                                        : "%d samples a pixel everywhere",
                                     a.mostSamples)
                           : printed("%d to %d samples a pixel (%.1f on average)", a.fewestSamples,
                                     a.mostSamples, a.meanSamples);
    text += ", estimated " + psnrText(estimatedPsnr(plan, a));
    if (plan.target.largestCodes)
        text += printed(", largest error about %.1f codes",
                        std::max(plan.depthLargest, a.estimatedLargest));
    return text;
}

ImageMetadata qualityMetadata(const Scene& scene, const QualityPlan& plan,
                              const AdaptiveOutcome& reached, double seconds,
                              std::string software) {
    RenderSettings settings = scene.render;
    settings.maxDepth = plan.maxDepth;
    settings.samplesPerPixel = reached.mostSamples;
    return makeImageMetadata(
        settings, seconds, std::move(software), describeTarget(plan.target),
        "depth " + std::to_string(plan.maxDepth) + ", " + describeReached(plan, reached));
}

}  // namespace whitted
