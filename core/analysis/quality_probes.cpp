#include "analysis/quality_probes.h"

#include <algorithm>

#include "analysis/tradeoff.h"

namespace whitted::planning {

namespace {

// The probe's longest side: enough pixels to see what deeper rays add (a
// mirror's reflection of a glass ball), few enough to cost a few one-sample
// renders of a small picture.
constexpr int kProbeSide = 320;
constexpr int kSmallestProbeSide = 40;
// A probe that traces for less than this runs on one thread: a second
// thread's start and join cost about as much as tracing a 40x30 probe of a
// few balls (0.06 ms), and planning a Draft renders five to seven of those.
// The probes grow dearer with depth; once one is over this, the rest use
// every core.
constexpr double kOneThreadProbeSeconds = 0.5e-3;
// Below this PSNR (Draft's 20 dB) the depth search's first probe render
// reaches 2 * kLookAhead - 1 levels, not kLookAhead: such a target's depth
// cut was 1 to 3 on every scene measured (docs/design/quality-planning.md,
// "Draft: one sample where it does"), and depth 1 or 2 took two renders, to 3 and then to 7 (for 1
// against 4); one render to 5 measures depths 0 to 2 against three deeper.
// Stricter targets cut deeper, where a longer first render would only add
// its levels to the one after it.
constexpr double kLongFirstProbeBelowDb = 30.0;

// The scene at the probe's size, one sample at each pixel's centre. The
// stricter the target, the smaller the error of the depth it must see, and
// the more samples the render will take anyway: an eighth of the picture's
// width and height below 30 dB (a search over a few depths then costs about
// a tenth of one sample a pixel), a quarter below 45 dB, half above; between
// kSmallestProbeSide and kProbeSide pixels along its longest side.
Scene probeScene(const Scene& scene, double psnrDb) {
    const int longest = std::max(scene.render.width, scene.render.height);
    const double share = psnrDb < 30.0 ? 0.125 : psnrDb < 45.0 ? 0.25 : 0.5;
    const double side = std::clamp(longest * share, double(kSmallestProbeSide), double(kProbeSide));
    TradeoffSettings s;
    s.samplesPerPixel = 1;
    s.maxDepth = scene.render.maxDepth;
    s.precision = scene.render.precision;
    s.resolutionScale = std::min(1.0, side / longest);
    return withSettings(scene, s);
}

}  // namespace

ProbeRenders::ProbeRenders(const Scene& scene, double psnrDb, const StopPredicate& stop)
    : probe_(probeScene(scene, psnrDb)),
      renderWidth_(scene.render.width),
      renderHeight_(scene.render.height),
      firstReach_(psnrDb < kLongFirstProbeBelowDb ? 2 * kLookAhead - 1 : kLookAhead),
      stop_(stop) {}

const Image& ProbeRenders::at(int depth, QualityPlan& plan) {
    auto found = byDepth_.find(depth);
    if (found != byDepth_.end()) return found->second;
    const int reach = depth == 0 && byDepth_.empty() ? firstReach_ : kLookAhead;
    const int deepest = std::min(kMaxDepth, depth + reach);
    std::vector<int> shallower;
    for (int d = depth; d < deepest; ++d)
        if (!byDepth_.count(d)) shallower.push_back(d);
    RenderResult r = trace(deepest, plan, {}, shallower);
    for (std::size_t k = 0; k < shallower.size(); ++k)
        byDepth_.emplace(shallower[k], std::move(r.atDepths[k]));
    byDepth_.emplace(deepest, std::move(r.image));
    return byDepth_.at(depth);
}

Image ProbeRenders::render(int depth, QualityPlan& plan, Precision precision, int samples) {
    const RenderSettings own = probe_.render;
    probe_.render.precision = precision;
    probe_.render.samplesPerPixel = samples;
    Image image = std::move(trace(depth, plan).image);
    probe_.render = own;
    return image;
}

bool ProbeRenders::probeIsThePicture() const {
    return probe_.render.width == renderWidth_ && probe_.render.height == renderHeight_;
}

const Image& ProbeRenders::pictureAt(int depth, QualityPlan& plan, int samples) {
    const std::pair key{depth, samples};
    auto found = pictureByDepth_.find(key);
    if (found != pictureByDepth_.end()) return found->second;
    return pictureByDepth_.emplace(key, atRenderSize(depth, plan, samples, {})).first->second;
}

std::pair<const Image*, const Image*> ProbeRenders::picturesAt(int depth, int reference,
                                                               QualityPlan& plan, int samples) {
    if (!pictureByDepth_.count({depth, samples}) && !pictureByDepth_.count({reference, samples}))
        picturesFrom(reference, {depth}, samples, plan);
    else if (!pictureByDepth_.count({depth, samples}))
        picturesAhead(depth, reference, samples, plan);
    return {&pictureAt(depth, plan, samples), &pictureAt(reference, plan, samples)};
}

Image ProbeRenders::atRenderSize(int depth, QualityPlan& plan, int samples,
                                 const std::vector<PixelRect>& regions) {
    return std::move(atRenderSize(depth, plan, samples, regions, {}).image);
}

const Image& ProbeRenders::keptAtRenderSize(int depth, QualityPlan& plan, int samples,
                                            const std::vector<PixelRect>& regions, int ahead) {
    if (ahead > 0) letGoShallower(keptByDepth_, depth, samples);
    KeptRegions& kept = keptRegions(depth, samples);
    std::vector<PixelRect> missing;
    for (const PixelRect& r : regions)
        if (!kept.allRendered(r)) missing.push_back(r);
    if (missing.empty()) return kept.image;
    std::vector<int> shallower;
    for (int d = depth; d < depth + ahead; ++d) shallower.push_back(d);
    RenderResult r = atRenderSize(depth + ahead, plan, samples, missing, shallower);
    for (std::size_t k = 0; k < shallower.size(); ++k)
        keptRegions(shallower[k], samples).keep(r.atDepths[k], missing);
    keptRegions(depth + ahead, samples).keep(r.image, missing);
    return kept.image;
}

void ProbeRenders::picturesFrom(int deepest, const std::vector<int>& shallower, int samples,
                                QualityPlan& plan) {
    RenderResult r = atRenderSize(deepest, plan, samples, {}, shallower);
    for (std::size_t k = 0; k < shallower.size(); ++k)
        pictureByDepth_.emplace(std::pair{shallower[k], samples}, std::move(r.atDepths[k]));
    pictureByDepth_.emplace(std::pair{deepest, samples}, std::move(r.image));
}

void ProbeRenders::picturesAhead(int depth, int reference, int samples, QualityPlan& plan) {
    int& renders = aheadRenders_[samples];
    const int reach = std::min(kLookAhead << std::min(renders, 4), kMostPicturesAhead);
    ++renders;
    int deepest = std::max(depth, std::min(depth + reach, reference) - 1);
    while (deepest > depth && pictureByDepth_.count({deepest, samples})) --deepest;
    std::vector<int> shallower;
    for (int d = depth; d < deepest; ++d)
        if (!pictureByDepth_.count({d, samples})) shallower.push_back(d);
    letGoShallower(pictureByDepth_, depth, samples);
    picturesFrom(deepest, shallower, samples, plan);
}

RenderResult ProbeRenders::atRenderSize(int depth, QualityPlan& plan, int samples,
                                        const std::vector<PixelRect>& regions,
                                        const std::vector<int>& alsoAtDepths) {
    const RenderSettings own = probe_.render;
    probe_.render.width = renderWidth_;
    probe_.render.height = renderHeight_;
    probe_.render.samplesPerPixel = samples;
    RenderResult r = trace(depth, plan, regions, alsoAtDepths);
    probe_.render = own;
    return r;
}

RenderResult ProbeRenders::trace(int depth, QualityPlan& plan,
                                 const std::vector<PixelRect>& regions,
                                 const std::vector<int>& alsoAtDepths) {
    probe_.render.maxDepth = depth;
    RenderOptions options = oneShotOptions();
    options.regions = regions;
    options.pruneBelowWeight = kQualityPruneWeight;
    options.alsoAtDepths = alsoAtDepths;
    options.bvhCache = &cache_;
    options.sceneValidated = validated_;  // the first render throws if it is not valid
    options.threads = oneThread_ ? 1 : 0;
    RenderResult r = whitted::render(probe_, options, {}, stop_);
    validated_ = true;
    oneThread_ = oneThread_ && r.tilesCpuSeconds < kOneThreadProbeSeconds;
    plan.probeRays += r.rays.total();
    return r;
}

ProbeRenders::KeptRegions& ProbeRenders::keptRegions(int depth, int samples) {
    KeptRegions& kept = keptByDepth_[{depth, samples}];
    if (kept.rendered.empty()) {
        kept.image = Image(renderWidth_, renderHeight_);
        kept.rendered.assign(std::size_t(renderWidth_) * renderHeight_, 0);
    }
    return kept;
}

}  // namespace whitted::planning
