// Rendering to a quality instead of to settings. A target names
// what the user will see against a converged render: a PSNR of the 8-bit
// picture and, optionally, the largest error of any pixel in 8-bit codes.
// planQuality() resolves it for one scene into a max_depth and the limits of
// an adaptive render (tracer/adaptive_sampling.h), and says why.
//
// The budget. The target's mean squared error M = 255^2 / 10^(PSNR / 10) is
// shared between what the depth cuts off (bias the samples cannot remove) and
// the sampling. The depth is the smallest whose picture, in a small probe
// render of pixel centres, differs from one three levels deeper by at most a
// tenth of M and a quarter of the largest error; the sampling gets what is
// left with a margin (kSamplingShare of it; docs/tradeoff.md measures how
// often that is enough), or, where the depth alone is over M and the target
// cannot be met, what it would get at a depth that fits. Where the target
// limits the largest error, the probe's depth is checked in one-sample
// renders of the whole picture against depth 16 (a feature of a few pixels
// can lie between the probe's centres, and light trapped in glass can come
// out more than three levels deeper; there the depth gets half the largest
// error), and a depth whose centres fail only by the largest error is
// judged with samples of the picture's pixels there. Both errors are
// measured, not bounded: the estimate of what the depth cuts off comes from
// the probe and the picture, that of the sampling from the render's own
// samples. The render, and every probe that plans it, follows no ray whose
// path passes on less than kQualityPruneWeight of its light, so a deep depth
// costs what its rays that still matter cost.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "image/image_metadata.h"
#include "scene/scene.h"
#include "tracer/adaptive_sampling.h"
#include "tracer/renderer.h"

namespace whitted {

struct QualityTarget {
    std::string name;  // "Draft", "Preview", "Final", or empty for a stated target
    double psnrDb = 35.0;
    std::optional<double> largestCodes;  // no pixel off by more than this many codes

    bool operator==(const QualityTarget&) const = default;
};

// The editor's and whitted-render's presets: Draft 20 dB; Preview 35 dB and
// no pixel off by more than 64 codes; Final 50 dB and 16 codes.
QualityTarget draftQuality();
QualityTarget previewQuality();
QualityTarget finalQuality();
// A preset by name, any case ("draft", "Final"); nullopt for any other name.
std::optional<QualityTarget> qualityPreset(std::string_view name);

// "Final: 50 dB, no pixel off by more than 16 codes"
std::string describeTarget(const QualityTarget& target);

// The mean squared error, in 8-bit codes squared, that a PSNR allows.
double allowedMse(double psnrDb);

inline constexpr double kDepthShareOfMse = 0.1;
inline constexpr double kDepthShareOfLargest = 0.25;
// The depth's share of the largest error where it is measured at the
// picture's own pixels: the probe's quarter leaves room for what falls
// between its centres, and there nothing does.
inline constexpr double kPictureShareOfLargest = 0.5;
inline constexpr double kSamplingShare = 0.8;
// A render to a quality follows no reflected or refracted ray whose path
// passes on less than this weight (RenderOptions::pruneBelowWeight): at most
// about a code near black for a ray of radiance 3. A clear glass ball's inner
// reflections (kr 0.1) end after three, instead of running to depth 16,
// while light kept at 0.9 a bounce among glass balls is followed to the end.
// On the generated fields a Final at depth 16 traced a quarter to a half of
// the rays and measured the same to 0.01 dB (docs/design/quality-planning.md).
inline constexpr double kQualityPruneWeight = 1e-4;
inline constexpr int kDefaultMaxSamples = 1024;
// Targets this loose with no limit on the largest error start with one sample
// at each pixel's centre (AdaptiveSampling::centresFirst): that is all a fixed
// render at one sample traces, and on the shipped scenes it measured 21 to 42
// dB at 320 and 640 pixels across. Above this, the centres would almost
// always be traced in vain (they cost a sixth to two fifths of the two
// samples every tile then takes).
inline constexpr double kCentresFirstUpToDb = 30.0;

struct QualityPlan {
    QualityTarget target;
    int maxDepth = 0;
    bool depthGiven = false;      // the caller fixed the depth; it was measured, not chosen
    bool depthShort = false;      // no depth the plan would go to cuts off little enough
    int referenceDepth = 0;       // the deep render the depths were measured against
    double depthMse = 0.0;        // the chosen depth's error against it, codes^2
    double depthLargest = 0.0;    // codes
    int depthLargestSamples = 1;  // a pixel, where the centres showed it (1: the centres)
    // depthMse and depthLargest were measured in the picture, not the probe.
    bool depthAtPictureSize = false;
    // They are the depth before's, bounds on this one's: the check went on
    // rendering only the pixels that depth left in doubt.
    int depthBoundsFrom = -1;
    double precisionMse = 0.0;  // float against double at that depth, codes^2, in the probe
    int precisionSamples = 1;   // a pixel, in the probe that measured it
    int probeWidth = 0, probeHeight = 0;
    std::uint64_t probeRays = 0;  // traced to choose the depth: part of the render's cost
    double cpuSeconds = 0.0;      // the planning thread's CPU time: part of it too
    AdaptiveSampling sampling;
    std::string why;       // the choices in a user's words, one line each
    bool stopped = false;  // `stop` said so while planning: the plan means nothing
};

// What a render to the plan reached, in words: "2 to 512 samples a pixel
// (119.3 on average), estimated 51.2 dB, largest error about 7.2 codes", or
// "1 sample a pixel everywhere, estimated 21.0 dB".
std::string describeReached(const QualityPlan& plan, const AdaptiveOutcome& reached);

// The image file's record of a render to a quality of `scene` (its size and
// precision): the depth chosen, the most samples a pixel took, and the
// target, depth and describeReached() in words.
ImageMetadata qualityMetadata(const Scene& scene, const QualityPlan& plan,
                              const AdaptiveOutcome& reached, double seconds, std::string software);

// What the plan chose, for the render that carries it out: the scene's
// depth, the options' limits for the samples and kQualityPruneWeight.
void applyPlan(const QualityPlan& plan, Scene& scene, RenderOptions& options);

// The PSNR that the plan's measured biases and the render's estimate add up
// to (psnrFromMse: +infinity when there is no error at all).
double estimatedPsnr(const QualityPlan& plan, const AdaptiveOutcome& outcome);

// The plan for rendering `scene` (its size and precision) to `target`, with
// at most maxSamples a pixel; `depth` fixes the depth instead of choosing it.
// `stop` is asked by the probe renders as a render asks it, and a plan it
// stopped says so.
QualityPlan planQuality(const Scene& scene, const QualityTarget& target,
                        int maxSamples = kDefaultMaxSamples,
                        std::optional<int> depth = std::nullopt, const StopPredicate& stop = {});

// Whether planQuality() plans both scenes alike: they differ at most in the
// samples per pixel and the depth, which it chooses. So choosing a preset,
// which sets both, keeps the plan made for the prediction in its tooltip.
bool plannedAlike(const Scene& a, const Scene& b);

}  // namespace whitted
