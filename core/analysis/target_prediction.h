// What a render to a quality target (quality_target.h) will take, predicted
// before it runs (the Render tab's figures for Draft,
// Preview and Final, which choose their own depth and samples per scene).
//
// Planning is deterministic, so the prediction makes the very plan the
// render will make, and then renders to it a sample of the picture's own
// tiles (speed_probe.h's probeTiles(), which lie on the adaptive render's
// grid of kAdaptiveTileEdge), each pixel's samples bit for bit the render's,
// the tiles judged among themselves (RenderOptions::regions), with the scene
// around them rendered too, for the estimates that look past a tile's
// border (RenderOptions::aroundRegions): each tile's ring at the samples
// the tile took rendered alone, then the tiles again beside it. Their mean
// samples and estimated error stand for the picture's; their rays and CPU
// time for the render's, scaled by the rays of a coarse one-sample picture
// over those of its pixels under the tiles (a ratio estimate: glass that
// traps light in a few tiles makes them dearer than their share of the
// pixels, and the coarse picture sees where they lie). As
// for fixed settings (speed_probe.h), the seconds are CPU time shared among
// the render's threads, so a prediction made beside the view's render is
// not slowed by it; the planning's seconds are the CPU time of the thread
// that planned, which traces its share of every probe.
//
// A picture of no more than kSpeedProbePixels would be rendered whole:
// `predicted` is false and `cannot` says why.
#pragma once

#include <cstdint>
#include <string>

#include "analysis/quality_target.h"
#include "scene/scene.h"
#include "tracer/renderer.h"

namespace whitted {

struct TargetPrediction {
    bool predicted = false;
    std::string cannot;       // why not, when not predicted
    QualityPlan plan;         // the render's own: its depth, limits and reasons
    double tilesShare = 0.0;  // of the picture's pixels, rendered to predict it
    double meanSamples = 0.0;
    double psnrDb = 0.0;          // what the render's estimate will say (estimatedPsnr())
    double largestCodes = 0.0;    // the tiles' estimated largest error
    double renderRays = 0.0;      // the adaptive render's, planning aside
    double planSeconds = 0.0;     // planning (the plan's cpuSeconds), part of the render
    double renderSeconds = 0.0;   // the adaptive render's
    std::uint64_t probeRays = 0;  // traced to predict, planning included
    double probeSeconds = 0.0;    // how long predicting took

    double seconds() const { return planSeconds + renderSeconds; }
    double rays() const { return double(plan.probeRays) + renderRays; }
};

// Every render it makes asks `stop` as a render asks it; once it says so,
// nothing is predicted (`cannot` says it was stopped).
TargetPrediction predictRenderTo(const Scene& scene, const QualityTarget& target,
                                 int maxSamples = kDefaultMaxSamples,
                                 const StopPredicate& stop = {});

// The same for a plan already made (by the render itself, or PlanMemo): the
// scene is that the plan was made for.
TargetPrediction predictRenderTo(const Scene& scene, const QualityPlan& plan,
                                 const StopPredicate& stop = {});

}  // namespace whitted
