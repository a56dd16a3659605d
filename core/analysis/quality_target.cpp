#include "analysis/quality_target.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>

#include "analysis/depth_truncation.h"
#include "analysis/tradeoff.h"
#include "base/thread_cpu_time.h"
#include "image/image_compare.h"
#include "image/image_error.h"
#include "tracer/renderer.h"

namespace whitted {

namespace {

// A pixel's estimated error is one draw from the same spread as its error,
// so the largest estimate of a tile is about as large as its largest error;
// each halving of the margin costs about four times the samples. 0.8 was
// chosen at 128x96 to 320x240, where tiles of 16 pixels hold so much of the
// picture that most are sampled well past what they need; at the 640x480
// the shipped scenes are saved at, 5 of 6 untuned fields' Previews came out
// 65 to 70 codes off (64 allowed). Under 0.6 all 5 whose plan promised the
// target met it, for about a fifth more time (bench_quality_fields at 640x480;
// docs/design/quality-planning.md).
constexpr double kLargestMargin = 0.6;
// The probe's longest side: enough pixels to see what deeper rays add (a
// mirror's reflection of a glass ball), few enough to cost a few one-sample
// renders of a small picture.
constexpr int kProbeSide = 320;
constexpr int kSmallestProbeSide = 40;
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
// A probe that traces for less than this runs on one thread: a second
// thread's start and join cost about as much as tracing a 40x30 probe of a
// few balls (0.06 ms), and planning a Draft renders five to seven of those.
// The probes grow dearer with depth; once one is over this, the rest use
// every core.
constexpr double kOneThreadProbeSeconds = 0.5e-3;
// How much deeper the render a depth is measured against goes.
constexpr int kLookAhead = 3;
// The most pictures of the render's size one render of the picture's check
// gives (picturesAhead()): eight of 1920x1080 are 200 MB.
constexpr int kMostPicturesAhead = 8;
// Below this PSNR (Draft's 20 dB) the depth search's first probe render
// reaches 2 * kLookAhead - 1 levels, not kLookAhead: such a target's depth
// cut was 1 to 3 on every scene measured (docs/design/quality-planning.md,
// "Draft: one sample where it does"), and depth 1 or 2 took two renders, to 3 and then to 7 (for 1
// against 4); one render to 5 measures depths 0 to 2 against three deeper.
// Stricter targets cut deeper, where a longer first render would only add
// its levels to the one after it.
constexpr double kLongFirstProbeBelowDb = 30.0;
// The deepest depth a plan chooses: kLookAhead short of the deepest SPEC
// allows, which it is judged against (judged against one level deeper, the
// last depth was taken in a room of lossless mirrors, where light comes out
// only every few levels). A render to a quality follows no ray too light to
// matter (kQualityPruneWeight), so a level deeper adds only the rays that
// light trapped among glass balls keeps bright: on the generated fields at
// 640x480, 0 to 29% more rays from depth 16 to 48, where pixels still
// changed by 35 to 160 codes. Capped at 16, as when every ray was followed
// and each level cost more than the last, 4 of the 12 Previews and Finals
// of those fields could not meet their target (docs/design/quality-planning.md,
// "The depth, measured").
constexpr int kDeepestPlanned = kMaxDepth - kLookAhead;

std::string format(const char* pattern, double a, double b = 0, double c = 0, double d = 0) {
    char text[256];
    std::snprintf(text, sizeof text, pattern, a, b, c, d);
    return text;
}

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

// The probe renders of one plan, by depth. The scene is copied and checked
// once and the tree of its spheres built once and refit for each (a build per
// probe was most of planning a field of 2500 balls; copying and checking
// 100,000 balls for each, a third of planning them), and the precision is
// compared at the chosen depth's render in the scene's own precision,
// already made for the depth. One render gives the picture at several
// depths (RenderOptions::alsoAtDepths): the depth search's probe at every
// depth up to kLookAhead past the one asked, and the picture's check its
// depth with the deepest.
class ProbeRenders {
  public:
    ProbeRenders(const Scene& scene, double psnrDb, const StopPredicate& stop)
        : probe_(probeScene(scene, psnrDb)),
          renderWidth_(scene.render.width),
          renderHeight_(scene.render.height),
          firstReach_(psnrDb < kLongFirstProbeBelowDb ? 2 * kLookAhead - 1 : kLookAhead),
          stop_(stop) {}

    const Scene& scene() const { return probe_; }

    // The probe's centres at `depth`, in the scene's precision. Not yet
    // traced: traced with those kLookAhead deeper, which the depth search
    // compares it with (and then goes on to), in one render (the search's
    // first, from depth 0, with firstReach_). It costs what the deepest of
    // them costs: the search to depth 8 took twelve renders, now three.
    const Image& at(int depth, QualityPlan& plan) {
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

    // The probe at `depth` with `samples` a pixel (1: its centres), in `precision`.
    Image render(int depth, QualityPlan& plan, Precision precision, int samples = 1) {
        const RenderSettings own = probe_.render;
        probe_.render.precision = precision;
        probe_.render.samplesPerPixel = samples;
        Image image = std::move(trace(depth, plan).image);
        probe_.render = own;
        return image;
    }

    int renderWidth() const { return renderWidth_; }
    int renderHeight() const { return renderHeight_; }
    bool probeIsThePicture() const {
        return probe_.render.width == renderWidth_ && probe_.render.height == renderHeight_;
    }

    // The picture at its own size at `depth`, `samples` a pixel (1: its centres).
    const Image& pictureAt(int depth, QualityPlan& plan, int samples) {
        const std::pair key{depth, samples};
        auto found = pictureByDepth_.find(key);
        if (found != pictureByDepth_.end()) return found->second;
        return pictureByDepth_.emplace(key, atRenderSize(depth, plan, samples, {})).first->second;
    }

    // The picture at `depth` and at the deeper `reference`, `samples` a pixel,
    // in one render where neither was made before. Each is pictureAt(depth,
    // plan, samples). Not the depths past `depth` too, in case the check goes
    // on to them: keeping twelve more pictures of 640x480 cost seed.json's
    // Preview more than the renders they would save. Once it has gone on, the
    // next few come in one render (picturesAhead()).
    std::pair<const Image*, const Image*> picturesAt(int depth, int reference, QualityPlan& plan,
                                                     int samples = 1) {
        if (!pictureByDepth_.count({depth, samples}) &&
            !pictureByDepth_.count({reference, samples}))
            picturesFrom(reference, {depth}, samples, plan);
        else if (!pictureByDepth_.count({depth, samples}))
            picturesAhead(depth, reference, samples, plan);
        return {&pictureAt(depth, plan, samples), &pictureAt(reference, plan, samples)};
    }

    // The `regions` of the picture at its own size, at `depth` with `samples`
    // a pixel in the scene's precision; zero elsewhere.
    Image atRenderSize(int depth, QualityPlan& plan, int samples,
                       const std::vector<PixelRect>& regions) {
        return std::move(atRenderSize(depth, plan, samples, regions, {}).image);
    }

    // atRenderSize() of `regions` at `depth`, with the pixels an earlier call
    // at the same depth and samples rendered kept and not rendered again (a
    // region is that part of the whole render, bit for bit); other pixels
    // may hold those earlier ones. Where it renders, it renders the `ahead`
    // depths after `depth` too, in the same render, and keeps them. The
    // check going on past a depth asks for the pixels still in doubt, fewer
    // at each level, at its reference and at the next depth: on a dense
    // field of glass balls, rendering them again for each level was most of
    // planning its Final. With `ahead`, the pixels kept of depths shallower
    // than `depth` are let go: a check going on does not ask for them again.
    const Image& keptAtRenderSize(int depth, QualityPlan& plan, int samples,
                                  const std::vector<PixelRect>& regions, int ahead = 0) {
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

  private:
    // Lets go of what `byDepth` (by depth and samples) keeps of `samples` a
    // pixel shallower than `depth`: a check going on past a depth does not
    // ask for it again.
    template <typename ByDepth>
    static void letGoShallower(ByDepth& byDepth, int depth, int samples) {
        std::erase_if(byDepth, [&](const auto& kept) {
            return kept.first.second == samples && kept.first.first < depth;
        });
    }

    // The picture at `deepest` and at each of `shallower`, `samples` a pixel, in one render.
    void picturesFrom(int deepest, const std::vector<int>& shallower, int samples,
                      QualityPlan& plan) {
        RenderResult r = atRenderSize(deepest, plan, samples, {}, shallower);
        for (std::size_t k = 0; k < shallower.size(); ++k)
            pictureByDepth_.emplace(std::pair{shallower[k], samples}, std::move(r.atDepths[k]));
        pictureByDepth_.emplace(std::pair{deepest, samples}, std::move(r.image));
    }

    // The check goes on past a depth that did not fit: the next depths short
    // of `reference` in one render, for it may well go on again (light
    // trapped among the glass balls of a generated field took the check at
    // 640x480 from depth 8 to 15, a render of the picture for each level).
    // kLookAhead of them, twice as many each time it goes on, up to
    // kMostPicturesAhead: pruned, a level deeper costs little more than the
    // last, and a dense field's Final went on from depth 34 to 55, seven
    // renders of the picture three levels apart. The pictures it has gone
    // past are not needed again.
    void picturesAhead(int depth, int reference, int samples, QualityPlan& plan) {
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

    RenderResult atRenderSize(int depth, QualityPlan& plan, int samples,
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

    // Pruned as the render to the plan is (kQualityPruneWeight): the depths
    // are compared by what that render would trace.
    RenderResult trace(int depth, QualityPlan& plan, const std::vector<PixelRect>& regions = {},
                       const std::vector<int>& alsoAtDepths = {}) {
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

    struct KeptRegions {
        Image image;
        std::vector<char> rendered;  // a pixel's flag, row by row
        void keep(const Image& from, const std::vector<PixelRect>& regions) {
            for (const PixelRect& r : regions)
                for (int y = r.y; y < r.y + r.height; ++y) {
                    std::copy(from.pixel(r.x, y), from.pixel(r.x, y) + 3 * r.width,
                              image.pixel(r.x, y));
                    std::fill_n(&rendered[std::size_t(y) * image.width + r.x], r.width, 1);
                }
        }
        bool allRendered(const PixelRect& r) const {
            for (int y = r.y; y < r.y + r.height; ++y) {
                const char* row = &rendered[std::size_t(y) * image.width];
                if (std::find(row + r.x, row + r.x + r.width, 0) != row + r.x + r.width)
                    return false;
            }
            return true;
        }
    };

    KeptRegions& keptRegions(int depth, int samples) {
        KeptRegions& kept = keptByDepth_[{depth, samples}];
        if (kept.rendered.empty()) {
            kept.image = Image(renderWidth_, renderHeight_);
            kept.rendered.assign(std::size_t(renderWidth_) * renderHeight_, 0);
        }
        return kept;
    }

    Scene probe_;
    int renderWidth_, renderHeight_;
    int firstReach_;  // levels past the depth asked that the first render traces
    const StopPredicate& stop_;
    bool validated_ = false;
    bool oneThread_ = true;
    BvhCache cache_;
    std::map<int, Image> byDepth_;                            // a map, so references stay valid
    std::map<std::pair<int, int>, Image> pictureByDepth_;     // by depth and samples
    std::map<std::pair<int, int>, KeptRegions> keptByDepth_;  // by depth and samples
    std::map<int, int> aheadRenders_;  // picturesAhead()'s renders, by samples
};

struct DepthError {
    double mse = 0.0, largest = 0.0;
};

DepthError depthError(const Image& image, const Image& reference) {
    const ErrorStats e = measureError(image, reference);
    return {e.rmseSrgb8 * e.rmseSrgb8, e.largest};
}

bool depthFits(const DepthError& e, const QualityTarget& t,
               double largestShare = kDepthShareOfLargest) {
    if (e.mse > kDepthShareOfMse * allowedMse(t.psnrDb)) return false;
    return !t.largestCodes || e.largest <= largestShare * *t.largestCodes;
}

// Most pixels of two depths are equal: those skip the sRGB curve.
double codesApart(const float* a, const float* b) {
    if (a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) return 0.0;
    return 255.0 * displayDifference(a, b);
}

// At least codesApart(a, b), from the 8-bit codes (displayDifferenceAtMost()):
// the pictures' checks need the exact difference only where it may be over
// a limit or the largest so far, and its std::pow was most of their loops.
double codesApartAtMost(const float* a, const float* b) {
    if (a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) return 0.0;
    return 255.0 * displayDifferenceAtMost(a, b);
}

// Two renders of one grid (the probe's or the picture's) at two depths: at
// the pixels' centres, and where the picture is also checked with several
// samples a pixel, those too.
struct DepthPair {
    const Image& shallow;
    const Image& deep;
    const Image* shallowSampled = nullptr;
    const Image* deepSampled = nullptr;
    int samples = 1;

    struct Apart {
        double centres = 0.0, sampled = 0.0;  // codes
    };
    Apart at(int x, int y) const { return apart(x, y, codesApart); }
    // At least at(x, y), without std::pow (codesApartAtMost()).
    Apart atMost(int x, int y) const { return apart(x, y, codesApartAtMost); }
    // Whether a pixel may hold a sliver over `limit`: its centres are over it,
    // or its samples' mean over 1/n of it (one of n samples sees a sliver,
    // and their mean shows 1/n of it).
    bool over(const Apart& a, double limit) const {
        return a.centres > limit || samples * a.sampled > limit;
    }

  private:
    Apart apart(int x, int y, double (*codes)(const float*, const float*)) const {
        Apart a{codes(shallow.pixel(x, y), deep.pixel(x, y))};
        if (shallowSampled)
            a.sampled = codes(shallowSampled->pixel(x, y), deepSampled->pixel(x, y));
        return a;
    }
};

// Pixels of the render, as renderPixelsUnder() finds them.
struct RenderPixels {
    std::vector<PixelRect> rects;
    std::size_t count = 0;
    double largestElsewhere = 0.0;
};

// What renderPixelsUnder() knows of one of the grid's pixels.
enum class GridPixel : char { Outside, Within, Over, Beside };

// Which of the grid's pixels renderPixelsUnder() finds in doubt: those that
// may hold a sliver over `codes` (DepthPair::over()), and those within
// `around` pixels of one.
struct Doubt {
    double codes;
    int around = 0;
};

// Each grid pixel of `parts`, Over or Within, and for those Within what they
// are apart at most (DepthPair::atMost(), exact where it may be over).
void markOver(const DepthPair& pair, const Doubt& doubt, const std::vector<PixelRect>& parts,
              std::vector<GridPixel>& marks, std::vector<double>& upTo) {
    const int width = pair.shallow.width;
    for (const PixelRect& part : parts)
        for (int y = part.y; y < part.y + part.height; ++y)
            for (int x = part.x; x < part.x + part.width; ++x) {
                DepthPair::Apart apart = pair.atMost(x, y);
                if (pair.over(apart, doubt.codes)) apart = pair.at(x, y);
                const std::size_t i = std::size_t(y) * width + x;
                marks[i] = pair.over(apart, doubt.codes) ? GridPixel::Over : GridPixel::Within;
                upTo[i] = std::max(apart.centres, apart.sampled);
            }
}

// Marks Beside the pixels Within `around` pixels of one Over.
void markBesideOver(int width, int height, int around, std::vector<GridPixel>& marks) {
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            if (marks[std::size_t(y) * width + x] != GridPixel::Over) continue;
            for (int ny = std::max(0, y - around); ny <= std::min(height - 1, y + around); ++ny)
                for (int nx = std::max(0, x - around); nx <= std::min(width - 1, x + around);
                     ++nx) {
                    GridPixel& mark = marks[std::size_t(ny) * width + nx];
                    if (mark == GridPixel::Within) mark = GridPixel::Beside;
                }
        }
}

// The render's pixels under the grid's pixels in doubt (Doubt), as
// rectangles (one for each run of such grid pixels along a row), and the
// largest difference of the grid's other pixels. Each of the render's
// pixels lies under one grid pixel: the grid pixel's edges rounded down to
// the render's. Only the grid's pixels `within`, if given.
RenderPixels renderPixelsUnder(const DepthPair& pair, const Doubt& doubt, int width, int height,
                               const std::vector<PixelRect>& within = {}) {
    const Image& grid = pair.shallow;
    const double across = double(width) / grid.width, down = double(height) / grid.height;
    std::vector<GridPixel> marks(std::size_t(grid.width) * grid.height, GridPixel::Outside);
    std::vector<double> upTo(marks.size(), 0.0);
    markOver(pair, doubt,
             within.empty() ? std::vector<PixelRect>{{0, 0, grid.width, grid.height}} : within,
             marks, upTo);
    if (doubt.around > 0) markBesideOver(grid.width, grid.height, doubt.around, marks);
    RenderPixels under;
    for (int py = 0; py < grid.height; ++py) {
        const int y0 = int(py * down), y1 = int((py + 1) * down);
        int runStart = -1;
        for (int px = 0; px <= grid.width; ++px) {
            const std::size_t i = std::size_t(py) * grid.width + px;
            const bool inDoubt =
                px < grid.width && (marks[i] == GridPixel::Over || marks[i] == GridPixel::Beside);
            if (inDoubt) {
                if (runStart < 0) runStart = px;
                continue;
            }
            // What it is at most would change the largest: then what it is.
            if (px < grid.width && marks[i] == GridPixel::Within &&
                upTo[i] > under.largestElsewhere) {
                const DepthPair::Apart apart = pair.at(px, py);
                under.largestElsewhere =
                    std::max({under.largestElsewhere, apart.centres, apart.sampled});
            }
            if (runStart < 0) continue;
            const int x0 = int(runStart * across), x1 = int(px * across);
            runStart = -1;
            if (x1 == x0 || y1 == y0) continue;
            under.rects.push_back({x0, y0, x1 - x0, y1 - y0});
            under.count += std::size_t(x1 - x0) * (y1 - y0);
        }
    }
    return under;
}

double largestDifference(const Image& a, const Image& b, const std::vector<PixelRect>& rects) {
    double largest = 0.0;
    for (const PixelRect& r : rects)
        for (int y = r.y; y < r.y + r.height; ++y)
            for (int x = r.x; x < r.x + r.width; ++x)
                if (codesApartAtMost(a.pixel(x, y), b.pixel(x, y)) > largest)
                    largest = std::max(largest, codesApart(a.pixel(x, y), b.pixel(x, y)));
    return largest;
}

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

// The picture's check looked for slivers with more samples than its centres.
std::string pictureSamplesWhy(const QualityPlan& p) {
    const int samples = pictureCheckSamples(*p.target.largestCodes, p.sampling.maxSamples);
    if (!p.depthAtPictureSize || samples == 1) return "";
    return format(" at the centres or with %.0f samples a pixel", samples);
}

std::string depthWhy(const QualityPlan& p) {
    std::string why =
        "depth " + std::to_string(p.maxDepth) + (p.depthGiven ? " (given)" : "") +
        format(", following no ray that passes on less than %g of the light", kQualityPruneWeight);
    why +=
        p.depthAtPictureSize
            ? format(": against depth %.0f, the picture's pixel centres change by ",
                     p.referenceDepth) +
                  (p.depthBoundsFrom >= 0 ? "at most " : "") +
                  format("%.3g codes^2 on average", p.depthMse)
            : format(": against depth %.0f, a %.0fx%.0f probe changes by %.3g codes^2 on average",
                     p.referenceDepth, p.probeWidth, p.probeHeight, p.depthMse);
    why += format(" (the target allows %.3g)", allowedMse(p.target.psnrDb));
    if (p.target.largestCodes)
        why += format(" and %.3g codes at most", p.depthLargest) + pictureSamplesWhy(p) +
               format(" (limit %.3g)", *p.target.largestCodes) +
               (p.depthLargestSamples > 1
                    ? format(", with %.0f samples a pixel of the picture where the centres "
                             "differ most",
                             p.depthLargestSamples)
                    : std::string());
    if (p.depthBoundsFrom >= 0)
        why += format(
            "; past depth %.0f the check rendered only the pixels it left in doubt, "
            "so elsewhere the figures are that depth's",
            p.depthBoundsFrom);
    if (!p.depthShort) return why;
    why += "\nno depth up to " + std::to_string(kDeepestPlanned) +
           " leaves the samples their share: rays trapped in glass or between mirrors "
           "still change the picture, ";
    // No number of samples takes back what the depth cuts off: a cut over
    // the whole limit makes a miss of the largest error likely.
    if (p.target.largestCodes && p.depthLargest > *p.target.largestCodes)
        return why + format("so a pixel is likely to be off by more than %.3g codes",
                            *p.target.largestCodes);
    return why + "so the target may be missed";
}

// The sampling's share of a target's MSE `total` once the depth and the
// precision have cut off `bias`. While the target can be met the samples get
// what is left, and at least the depth's share. Once the bias alone is over
// the target, chasing it with samples buys a fraction of a dB for several
// times the render (on a dense glass field, 602 samples a pixel instead of
// 108, for 46.2 dB instead of 45.3): the samples are then held to the noise
// of a picture that meets the target.
double samplingMse(double total, double bias) {
    if (bias > total) return kSamplingShare * (1.0 - kDepthShareOfMse) * total;
    return kSamplingShare * std::max(total - bias, kDepthShareOfMse * total);
}

std::string outOfReachWhy(const QualityPlan& p, double total) {
    return std::string("\nthe ") + (p.depthGiven ? "given depth" : "deepest depth planned") +
           (p.depthMse > total ? " alone cuts" : " and float together cut") +
           " off more than the target allows: it cannot be met, so the samples aim for " +
           format("the noise of a picture that meets it (%.3g codes^2)", p.sampling.allowedMse);
}

std::string samplingWhy(const QualityPlan& p) {
    std::string why = p.sampling.centresFirst
                          ? "samples: one at each pixel's centre, its error estimated from "
                            "neighbouring pixels; then "
                          : "samples: ";
    why += format("each tile until the picture's estimated error is under %.3g codes^2",
                  p.sampling.allowedMse);
    if (p.target.largestCodes)
        why += format(" and no pixel's estimate over %.3g codes", p.sampling.allowedLargest);
    return why + ", at most " + std::to_string(p.sampling.maxSamples) + " a pixel";
}

}  // namespace

QualityTarget draftQuality() {
    return {"Draft", 20.0, std::nullopt};
}
QualityTarget previewQuality() {
    return {"Preview", 35.0, 64.0};
}
QualityTarget finalQuality() {
    return {"Final", 50.0, 16.0};
}

std::optional<QualityTarget> qualityPreset(std::string_view name) {
    std::string lower(name);
    for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (lower == "draft") return draftQuality();
    if (lower == "preview") return previewQuality();
    if (lower == "final") return finalQuality();
    return std::nullopt;
}

std::string describeTarget(const QualityTarget& t) {
    std::string text =
        (t.name.empty() ? std::string() : t.name + ": ") + format("%.3g dB", t.psnrDb);
    if (t.largestCodes) text += format(", no pixel off by more than %.3g codes", *t.largestCodes);
    return text;
}

double allowedMse(double psnrDb) {
    return 255.0 * 255.0 / std::pow(10.0, psnrDb / 10.0);
}

std::string describeReached(const QualityPlan& plan, const AdaptiveOutcome& a) {
    std::string text = a.fewestSamples == a.mostSamples
                           ? format(a.mostSamples == 1 ? "%.0f sample a pixel everywhere"
                                                       : "%.0f samples a pixel everywhere",
                                    a.mostSamples)
                           : format("%.0f to %.0f samples a pixel (%.1f on average)",
                                    a.fewestSamples, a.mostSamples, a.meanSamples);
    text += ", estimated " + psnrText(estimatedPsnr(plan, a));
    if (plan.target.largestCodes)
        text += format(", largest error about %.1f codes",
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

void applyPlan(const QualityPlan& plan, Scene& scene, RenderOptions& options) {
    scene.render.maxDepth = plan.maxDepth;
    options.adaptive = plan.sampling;
    options.pruneBelowWeight = kQualityPruneWeight;
}

double estimatedPsnr(const QualityPlan& plan, const AdaptiveOutcome& outcome) {
    return psnrFromMse(plan.depthMse + plan.precisionMse + outcome.estimatedMse);
}

bool plannedAlike(const Scene& a, const Scene& b) {
    return a.render.width == b.render.width && a.render.height == b.render.height &&
           a.render.precision == b.render.precision && sameSceneContent(a, b);
}

QualityPlan planQuality(const Scene& scene, const QualityTarget& target, int maxSamples,
                        std::optional<int> depth, const StopPredicate& stop) {
    const double start = threadCpuSeconds();
    QualityPlan plan;
    plan.target = target;
    // A stopped probe is an empty picture: the depth search then ends at
    // once, and the plan is marked as stopped below.
    ProbeRenders probes(scene, target.psnrDb, stop);
    planDepth(probes, depth, maxSamples, plan);
    checkDepthAtPictureSize(probes, maxSamples, plan);
    plan.sampling.maxSamples = std::max(1, maxSamples);
    plan.sampling.centresFirst = !target.largestCodes && target.psnrDb <= kCentresFirstUpToDb;
    planPrecision(probes, plan);
    plan.stopped = stop && stop();
    const double total = allowedMse(target.psnrDb);
    const double bias = plan.depthMse + plan.precisionMse;
    plan.sampling.allowedMse = samplingMse(total, bias);
    // The largest errors of the depth and of the sampling are seldom in the
    // same pixel (light trapped in glass; edges), so each gets the whole limit.
    if (target.largestCodes) plan.sampling.allowedLargest = kLargestMargin * *target.largestCodes;
    plan.why = depthWhy(plan) + "\n";
    if (scene.render.precision == Precision::Float)
        plan.why +=
            format("float against double: %.3g codes^2 in the same probe", plan.precisionMse) +
            (plan.precisionSamples > 1 ? format(", at %.0f samples a pixel", plan.precisionSamples)
                                       : std::string()) +
            "\n";
    plan.why += samplingWhy(plan);
    if (bias > total) plan.why += outOfReachWhy(plan, total);
    plan.cpuSeconds = threadCpuSeconds() - start;
    return plan;
}

}  // namespace whitted
