#include "analysis/quality_depth.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "analysis/quality_doubt.h"

namespace whitted::planning {

namespace {

// Float's difference from double, at the probes' centres, that is measured
// again with more samples a pixel (planPrecision()): a share of the budget
// like the depth's, below which the extra probes would cost more than the
// samples they might save.
constexpr double kPrecisionShareOfMse = 0.1;
constexpr int kPrecisionSamples = 8;
// A depth whose centres fail only by the largest error is judged again at the
// picture's own pixels under the centres over the share, with this many
// samples each (largestWithSamples()), unless they are more than this share
// of the picture: then the samples would cost more than the depth they might
// save, and the centres' verdict stands.
constexpr int kDepthLargestSamples = 8;
constexpr double kMostRenderPixelsJudged = 0.25;
// At the picture's size, the pixels this many pixels around one whose
// centres may hold a sliver are judged with samples too: light trapped in a
// small glass ball comes out in a thin curve, which one centre meets and
// the next pixel's passes by. On bench_quality_fields' fifth field at
// 640x480 depth 36 cut 161 codes off one centre, and 64 samples showed 74
// codes cut off the pixel beside it, whose centre saw nothing (Preview
// allows 64).
constexpr int kAroundInDoubt = 1;

bool depthFits(const DepthError& e, const QualityTarget& t,
               double largestShare = kDepthShareOfLargest) {
    if (e.mse > kDepthShareOfMse * allowedMse(t.psnrDb)) return false;
    return !t.largestCodes || e.largest <= largestShare * *t.largestCodes;
}

}  // namespace

// A pixel centre sees nothing of light trapped in glass that falls between
// the centres: on bench_quality_fields' tenth field depth 10 cut 16.5 codes
// off a pixel at 8 samples where its centre and its eight neighbours' showed
// none. The smaller the limit, the thinner a sliver that can break it (one
// sixteenth of a pixel 255 codes off breaks Final's 16), so besides its
// centres the picture is checked with kPictureCheckCodes / limit samples a
// pixel: two for Final, none for Preview; never more than the render takes.
// They cost a Final a few of its hundred samples.
constexpr double kPictureCheckCodes = 32.0;

int pictureCheckSamples(double largestCodes, int maxSamples) {
    const int samples = int(std::lround(kPictureCheckCodes / largestCodes));
    return std::clamp(samples, 1, std::clamp(maxSamples, 1, kDepthLargestSamples));
}

namespace {

// Whether the depth's probe at the pixels' centres fails only by its largest
// error, and by no more than the whole limit: then, as for the precision
// (planPrecision()), the centres may show whole a difference in a sliver of a
// pixel that a render of several samples shares out over the pixel. A centre
// off by more than the whole limit was seldom so thin a sliver (field.json at
// Preview: 67.6 codes, 39.2 with samples, 16 allowed).
bool largestAtCentresOnly(const DepthError& e, const QualityTarget& t, double mseShare) {
    return t.largestCodes && e.mse <= mseShare &&
           e.largest > kDepthShareOfLargest * *t.largestCodes && e.largest <= *t.largestCodes;
}

// How sampledLargest() renders. The probe's search judges each depth against
// its own reference; the picture's check judges every depth against depth 64,
// whose pixels it keeps (ProbeRenders::keptAtRenderSize()), and once it goes
// on past a depth, renders its pixels several depths to a render.
enum class SampledCheck { ProbeSearch, Picture, PictureGoingOn };

// The largest error of `depth` against `reference` as the picture's own
// pixels show it with kDepthLargestSamples each, the same samples at both,
// where the grid's pair may hold a sliver over `largestShare` of the limit;
// with the grid's other pixels' largest. Nothing where those pixels are too
// many. At the picture's own pixels, not the probe's: a probe's pixel is two
// to eight of the picture's across, and averaging a sliver over it
// understated what one of the picture's pixels shows (two of twelve
// generated fields missed their target).
// The largest difference of `over`'s pixels of the picture at `depth` and
// `reference` with kDepthLargestSamples each, and of the pixels elsewhere.
double sampledLargest(ProbeRenders& probes, QualityPlan& plan, const RenderPixels& over, int depth,
                      int reference, SampledCheck check) {
    if (over.rects.empty()) return over.largestElsewhere;
    plan.depthLargestSamples = kDepthLargestSamples;
    auto largest = [&](const Image& atDepth, const Image& atReference) {
        return std::max(over.largestElsewhere, largestDifference(atDepth, atReference, over.rects));
    };
    auto rendered = [&](int at) {
        return probes.atRenderSize(at, plan, kDepthLargestSamples, over.rects);
    };
    if (check == SampledCheck::ProbeSearch) return largest(rendered(depth), rendered(reference));
    const Image& atReference =
        probes.keptAtRenderSize(reference, plan, kDepthLargestSamples, over.rects);
    const int ahead = std::min(kMostPicturesAhead, reference - depth) - 1;
    if (check == SampledCheck::PictureGoingOn && ahead > 0)
        return largest(
            probes.keptAtRenderSize(depth, plan, kDepthLargestSamples, over.rects, ahead),
            atReference);
    return largest(rendered(depth), atReference);
}

// The pixels of the picture a depth's check at its size left in doubt (over
// kPictureShareOfLargest of the limit at the centres or with samples, and
// those kAroundInDoubt around them), and the largest difference of all the
// others.
using InDoubt = RenderPixels;

std::optional<double> largestWithSamples(ProbeRenders& probes, QualityPlan& plan,
                                         const DepthPair& pair, int depth, int reference,
                                         double largestShare, SampledCheck check,
                                         InDoubt* inDoubt = nullptr) {
    const Doubt doubt{largestShare * *plan.target.largestCodes,
                      check == SampledCheck::ProbeSearch ? 0 : kAroundInDoubt};
    RenderPixels over = renderPixelsUnder(pair, doubt, probes.renderWidth(), probes.renderHeight());
    const double picture = double(probes.renderWidth()) * probes.renderHeight();
    if (double(over.count) > kMostRenderPixelsJudged * picture) return std::nullopt;
    const double largest = sampledLargest(probes, plan, over, depth, reference, check);
    if (inDoubt) *inDoubt = std::move(over);
    return largest;
}

// A depth's error at the picture's size, and the pixels it left in doubt,
// if it judged them with samples (none: it did not, or they were too many).
struct PictureDepthError {
    DepthError error;
    std::optional<InDoubt> inDoubt;
    int boundsFrom = -1;  // the depth whose MSE and other pixels' largest bound these
};

// The error of `depth` against `reference` at the picture's own size: its
// centres and pictureCheckSamples() a pixel, and where a pixel may hold a
// sliver over kPictureShareOfLargest of the limit, kDepthLargestSamples
// (largestWithSamples()). The MSE is the centres'. `goingOn`: the check has
// gone on past a depth already, and those pixels come several depths to a
// render.
PictureDepthError pictureDepthError(ProbeRenders& probes, QualityPlan& plan, int depth,
                                    int reference, int maxSamples, bool goingOn) {
    const auto [shallow, deep] = probes.picturesAt(depth, reference, plan);
    DepthPair pair{*shallow, *deep};
    DepthError e = depthError(pair.shallow, pair.deep);
    DepthPair::Apart largest{e.largest};
    pair.samples = pictureCheckSamples(*plan.target.largestCodes, maxSamples);
    if (pair.samples > 1) {
        std::tie(pair.shallowSampled, pair.deepSampled) =
            probes.picturesAt(depth, reference, plan, pair.samples);
        largest.sampled = depthError(*pair.shallowSampled, *pair.deepSampled).largest;
        e.largest = std::max(e.largest, largest.sampled);
    }
    plan.depthLargestSamples = 1;
    // Whatever the largest: at the picture's size a pixel off by more than
    // the whole limit may still be a sliver.
    PictureDepthError checked{e, std::nullopt};
    if (maxSamples > 1 && pair.over(largest, kPictureShareOfLargest * *plan.target.largestCodes)) {
        InDoubt inDoubt;
        const SampledCheck check = goingOn ? SampledCheck::PictureGoingOn : SampledCheck::Picture;
        if (auto sampled = largestWithSamples(probes, plan, pair, depth, reference,
                                              kPictureShareOfLargest, check, &inDoubt)) {
            checked.error.largest = *sampled;
            checked.inDoubt = std::move(inDoubt);
        }
    }
    return checked;
}

// pictureDepthError() of a depth deeper than one whose check left pixels in
// doubt, against the same reference, with only those pixels rendered: each
// level deeper adds light and takes none away (colours, weights and lights
// are never negative), so a pixel within its share at a depth is within it
// deeper too, and the MSE does not grow (but for the last bit of rounding:
// EachLevelDeeperAddsLight_NoPixelDarker). The verdict is the one the whole
// picture gives; the MSE and the other pixels' largest are the shallower
// depth's, bounds on this one's. Checking fields at 640x480 went on from
// depth 8 to 15 (bench_quality_fields), a render of the whole picture for
// every three levels; mirrors.json's Preview from 6 to 8.
PictureDepthError inDoubtDepthError(ProbeRenders& probes, QualityPlan& plan, int depth,
                                    int reference, int maxSamples, const InDoubt& before,
                                    double mseBefore, int boundsFrom) {
    const Doubt doubt{kPictureShareOfLargest * *plan.target.largestCodes, kAroundInDoubt};
    const Image shallow = probes.atRenderSize(depth, plan, 1, before.rects);
    DepthPair pair{shallow, probes.pictureAt(reference, plan, 1)};
    Image shallowSampled;
    pair.samples = pictureCheckSamples(*plan.target.largestCodes, maxSamples);
    if (pair.samples > 1) {
        shallowSampled = probes.atRenderSize(depth, plan, pair.samples, before.rects);
        pair.shallowSampled = &shallowSampled;
        pair.deepSampled = &probes.pictureAt(reference, plan, pair.samples);
    }
    InDoubt inDoubt =
        renderPixelsUnder(pair, doubt, probes.renderWidth(), probes.renderHeight(), before.rects);
    inDoubt.largestElsewhere = std::max(inDoubt.largestElsewhere, before.largestElsewhere);
    plan.depthLargestSamples = 1;
    const double largest =
        sampledLargest(probes, plan, inDoubt, depth, reference, SampledCheck::PictureGoingOn);
    return {{mseBefore, largest}, std::move(inDoubt), boundsFrom};
}

}  // namespace

// The probe sees one of every four to sixty-four of the picture's pixels, and
// a feature of a few pixels can lie between its centres: light trapped in a
// small glass ball, 94 codes brighter three levels deeper, where every probe
// centre around it was unchanged (bench_quality_fields, docs/design/quality-planning.md). So
// for a target with a limit on the largest error, the probe's depth is
// checked at the picture's own size, and taken deeper until it fits there or
// reaches kDeepestPlanned. It is checked against the deepest depth SPEC
// allows, not three levels deeper: light trapped among glass balls can come
// out five levels or more past a depth (on bench_quality_fields' seventeenth
// field a pixel changes by 5 codes from depth 8 to 11, and by 78 from 12 to
// 14; on its fifth at 640x480 by 113 from depth 40 to 48). Where the
// probe's depth holds, it costs one render of the picture's centres at the
// reference's depth, which gives the probe's depth too, and for Final one of
// two samples a pixel (pictureCheckSamples()), against the two or more
// samples a pixel such a render takes; the deep ones follow only the rays
// that can still matter (kQualityPruneWeight). The sampled pictures come
// several depths to a render as the centres do: a Final's planning traced
// 0.58 to 0.81 of the rays it did with a render for each (docs/design/quality-planning.md).
void checkDepthAtPictureSize(ProbeRenders& probes, int maxSamples, QualityPlan& plan) {
    if (!plan.target.largestCodes || plan.depthGiven || probes.probeIsThePicture()) return;
    // A probe that found no depth that fits and is already at the deepest
    // keeps its verdict: the picture cannot take it deeper.
    if (plan.depthShort && plan.maxDepth >= kDeepestPlanned) return;
    std::optional<InDoubt> inDoubt;  // what the depth before left, where its MSE fitted
    const int firstDepth = plan.maxDepth;
    for (int depth = plan.maxDepth; depth <= kDeepestPlanned; ++depth) {
        const int reference = kMaxDepth;
        const PictureDepthError checked =
            inDoubt && reference == plan.referenceDepth
                ? inDoubtDepthError(probes, plan, depth, reference, maxSamples, *inDoubt,
                                    plan.depthMse,
                                    plan.depthBoundsFrom >= 0 ? plan.depthBoundsFrom : depth - 1)
                : pictureDepthError(probes, plan, depth, reference, maxSamples, depth > firstDepth);
        const DepthError& e = checked.error;
        plan.maxDepth = depth;
        plan.referenceDepth = reference;
        plan.depthMse = e.mse;
        plan.depthLargest = e.largest;
        plan.depthAtPictureSize = true;
        plan.depthBoundsFrom = checked.boundsFrom;
        plan.depthShort = !depthFits(e, plan.target, kPictureShareOfLargest);
        if (!plan.depthShort) return;
        const bool mseFits = e.mse <= kDepthShareOfMse * allowedMse(plan.target.psnrDb);
        inDoubt = mseFits ? checked.inDoubt : std::nullopt;
    }
    plan.depthShort = true;
}

// Chooses (or, when given, measures) the depth, filling the plan's depth
// fields: the smallest depth whose probe differs from the probe kLookAhead
// levels deeper by less than the depth's share of the target. Each level
// deeper passes on at most the scene's kr + kt of the last, so what lies past
// the look-ahead is smaller still, unless rays bounce without losing weight
// (depthWithinTolerance() follows those much further, but at a cost of
// minutes on a field of glass balls, too much for planning a render).
// A depth that fails at the pixels' centres only by its largest error is
// judged by its largest error at the render's pixels with samples, unless the
// render takes one sample a pixel at most.
void planDepth(ProbeRenders& probes, std::optional<int> given, int maxSamples, QualityPlan& plan) {
    plan.probeWidth = probes.scene().render.width;
    plan.probeHeight = probes.scene().render.height;
    const double mseShare = kDepthShareOfMse * allowedMse(plan.target.psnrDb);
    auto measure = [&](int depth) {
        plan.maxDepth = depth;
        plan.referenceDepth = std::min(kMaxDepth, depth + kLookAhead);
        const Image& shallow = probes.at(depth, plan);
        const Image& deep = probes.at(plan.referenceDepth, plan);
        DepthError e = depthError(shallow, deep);
        plan.depthLargestSamples = 1;
        if (maxSamples > 1 && largestAtCentresOnly(e, plan.target, mseShare))
            e.largest =
                largestWithSamples(probes, plan, {shallow, deep}, depth, plan.referenceDepth,
                                   kDepthShareOfLargest, SampledCheck::ProbeSearch)
                    .value_or(e.largest);
        plan.depthMse = e.mse;
        plan.depthLargest = e.largest;
        return e;
    };
    if (given) {
        plan.depthGiven = true;
        measure(*given);
        return;
    }
    // Failing both shares up to kDeepestPlanned: the first depth within the
    // MSE share whose largest error is within the whole limit, else the first
    // within the MSE share, else the deepest; the plan then says what is short.
    std::optional<int> withinLimit, withinMse;
    for (int depth = 0; depth <= kDeepestPlanned; ++depth) {
        const DepthError e = measure(depth);
        if (depthFits(e, plan.target)) return;
        if (e.mse > mseShare) continue;
        if (!withinMse) withinMse = depth;
        if (!withinLimit && (!plan.target.largestCodes || e.largest <= *plan.target.largestCodes))
            withinLimit = depth;
    }
    plan.depthShort = true;
    measure(withinLimit.value_or(withinMse.value_or(kDeepestPlanned)));
}

// What float arithmetic changes against double at the chosen depth, in the
// same probe: the reference a user compares with is converged, in double.
// Where float and double part in a sliver of a pixel (a ray grazing a glass
// ball), the centre shows the whole difference or none, while a render of
// many samples averages it over the pixel: the error it keeps is the square
// of the sliver's share, not the share. So where the centres' difference
// would take a real part of the budget, it is measured again with
// kPrecisionSamples a pixel, in both precisions at the same sample positions,
// and that is taken: a difference the samples share out is then counted as
// the sampling counts it, and what is left is float's bias. Not where the
// render may stop at the centres (one sample a pixel at most, or
// centresFirst): there the centres' difference is the one it shows.
void planPrecision(ProbeRenders& probes, QualityPlan& plan) {
    if (probes.scene().render.precision == Precision::Double) return;
    const int depth = plan.maxDepth;
    const Image inDouble = probes.render(depth, plan, Precision::Double);
    plan.precisionMse = depthError(probes.at(depth, plan), inDouble).mse;
    const bool severalSamples = plan.sampling.maxSamples > 1 && !plan.sampling.centresFirst;
    if (!severalSamples ||
        plan.precisionMse <= kPrecisionShareOfMse * allowedMse(plan.target.psnrDb))
        return;
    plan.precisionSamples = kPrecisionSamples;
    plan.precisionMse = depthError(probes.render(depth, plan, Precision::Float, kPrecisionSamples),
                                   probes.render(depth, plan, Precision::Double, kPrecisionSamples))
                            .mse;
}

}  // namespace whitted::planning
