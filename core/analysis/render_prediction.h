// What a render with a scene's own settings (samples per pixel, max depth,
// precision) will cost and how far from converged it will be, predicted for
// a scene never measured, from small probe renders of it:
//
// - What the depth cuts off and what float changes: planQuality()'s probes,
//   the depth measured against three levels deeper (quality_target.h).
// - The sampling noise: renders of a probe of at most kNoiseProbeSide pixels
//   along its longest side at 2, 4, ... samples a pixel, each estimating its
//   own error from the halves of its samples (adaptive_sampling.h); counts
//   beyond the probes' follow the slope of the last two. A Whitted picture's
//   noise is all at edges (of balls, shadows, checks, reflections) inside a
//   pixel, whose share of the pixels shrinks as the pixels do: the probe's
//   noise is scaled by its side over the picture's, and by a factor fitted
//   on the shipped scenes (render_prediction.cpp).
// - The rays: the probe's rays per sample at the scene's depth, times the
//   picture's samples.
// - The seconds: those rays at the costs that timed renders of the scene at
//   two small sizes show (speed_probe.h).
//
// For a picture under kNoiseProbeSide / 2 pixels across, the probes would
// cost more than the render: `predicted` is false and `cannot` says why.
#pragma once

#include <cstdint>
#include <string>

#include "scene/scene.h"
#include "tracer/renderer.h"

namespace whitted {

inline constexpr int kNoiseProbeSide = 160;
inline constexpr int kNoiseProbeSamples = 16;  // the most samples a probe takes

struct RenderPrediction {
    bool predicted = false;
    std::string cannot;      // why not, when not predicted
    double mseCodes2 = 0.0;  // of the 8-bit picture against a converged one
    double psnrDb = 0.0;
    double depthMse = 0.0, precisionMse = 0.0, samplingMse = 0.0;  // its parts
    double samplingSlope = 0.0;   // the noise falls like samples^-slope past the probes
    double rays = 0.0;            // the render's
    double seconds = 0.0;         // the render's on this machine, as fast as the probes ran
    std::uint64_t probeRays = 0;  // what predicting traced
    double probeSeconds = 0.0;    // how long predicting took
};

// Every probe render asks `stop` as a render asks it; once it says so,
// nothing is predicted (`cannot` says it was stopped).
RenderPrediction predictRender(const Scene& scene, const StopPredicate& stop = {});

}  // namespace whitted
