// The probe renders a quality plan is made from (planQuality(),
// quality_target.h): the scene at a small size, and the picture at its own,
// at the depths the plan asks for, each rendered once and kept.
#pragma once

#include <map>
#include <utility>
#include <vector>

#include "analysis/quality_target.h"
#include "tracer/renderer.h"

namespace whitted::planning {

// How much deeper the render a depth is measured against goes.
constexpr int kLookAhead = 3;
// The most pictures of the render's size one render of the picture's check
// gives (picturesAhead()): eight of 1920x1080 are 200 MB.
constexpr int kMostPicturesAhead = 8;

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
    ProbeRenders(const Scene& scene, double psnrDb, const StopPredicate& stop);

    const Scene& scene() const { return probe_; }

    // The probe's centres at `depth`, in the scene's precision. Not yet
    // traced: traced with those kLookAhead deeper, which the depth search
    // compares it with (and then goes on to), in one render (the search's
    // first, from depth 0, with firstReach_). It costs what the deepest of
    // them costs: the search to depth 8 took twelve renders, now three.
    const Image& at(int depth, QualityPlan& plan);

    // The probe at `depth` with `samples` a pixel (1: its centres), in `precision`.
    Image render(int depth, QualityPlan& plan, Precision precision, int samples = 1);

    int renderWidth() const { return renderWidth_; }
    int renderHeight() const { return renderHeight_; }
    bool probeIsThePicture() const;

    // The picture at its own size at `depth`, `samples` a pixel (1: its centres).
    const Image& pictureAt(int depth, QualityPlan& plan, int samples);

    // The picture at `depth` and at the deeper `reference`, `samples` a pixel,
    // in one render where neither was made before. Each is pictureAt(depth,
    // plan, samples). Not the depths past `depth` too, in case the check goes
    // on to them: keeping twelve more pictures of 640x480 cost seed.json's
    // Preview more than the renders they would save. Once it has gone on, the
    // next few come in one render (picturesAhead()).
    std::pair<const Image*, const Image*> picturesAt(int depth, int reference, QualityPlan& plan,
                                                     int samples = 1);

    // The `regions` of the picture at its own size, at `depth` with `samples`
    // a pixel in the scene's precision; zero elsewhere.
    Image atRenderSize(int depth, QualityPlan& plan, int samples,
                       const std::vector<PixelRect>& regions);

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
                                  const std::vector<PixelRect>& regions, int ahead = 0);

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
                      QualityPlan& plan);

    // The check goes on past a depth that did not fit: the next depths short
    // of `reference` in one render, for it may well go on again (light
    // trapped among the glass balls of a generated field took the check at
    // 640x480 from depth 8 to 15, a render of the picture for each level).
    // kLookAhead of them, twice as many each time it goes on, up to
    // kMostPicturesAhead: pruned, a level deeper costs little more than the
    // last, and a dense field's Final went on from depth 34 to 55, seven
    // renders of the picture three levels apart. The pictures it has gone
    // past are not needed again.
    void picturesAhead(int depth, int reference, int samples, QualityPlan& plan);

    RenderResult atRenderSize(int depth, QualityPlan& plan, int samples,
                              const std::vector<PixelRect>& regions,
                              const std::vector<int>& alsoAtDepths);

    // Pruned as the render to the plan is (kQualityPruneWeight): the depths
    // are compared by what that render would trace.
    RenderResult trace(int depth, QualityPlan& plan, const std::vector<PixelRect>& regions = {},
                       const std::vector<int>& alsoAtDepths = {});

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

    KeptRegions& keptRegions(int depth, int samples);

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

}  // namespace whitted::planning
