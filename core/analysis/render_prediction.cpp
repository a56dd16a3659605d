#include "analysis/render_prediction.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <map>

#include "analysis/quality_target.h"
#include "analysis/speed_probe.h"
#include "analysis/tradeoff.h"
#include "base/elapsed.h"
#include "image/image_error.h"
#include "tracer/renderer.h"

namespace whitted {

namespace {

// Fitted on the six shipped scenes at 320x240 (bench_prediction, docs/design/quality-planning.md),
// never on the generated scenes the tests check. The probes' estimate, scaled
// to the picture, is 1.7 times the noise a fixed render then measures (the
// halves of stratified samples differ more than their mean errs, and the
// render's CMJ patterns err less than the probes' Sobol ones); and past 16
// samples the noise falls like samples^-1.3 or slower, less steeply than
// between 8 and 16 (1.4 to 1.7 on those scenes).
constexpr double kNoiseCalibration = 0.59;
constexpr double kSteepestLongRunSlope = 1.3;

struct NoiseProbe {
    std::map<int, double> mseAt;  // samples a pixel -> the probe's estimated noise, codes^2
    double scale = 1.0;           // probe side over picture side
    double raysPerSample = 0.0;   // per pixel
    std::uint64_t rays = 0;
};

// The probe at 2, 4, ... kNoiseProbeSamples samples, each render sampling
// every tile with content to its count (no error is small enough to stop).
NoiseProbe probeNoise(const Scene& scene, const StopPredicate& stop) {
    const int longest = std::max(scene.render.width, scene.render.height);
    TradeoffSettings s{1, scene.render.maxDepth, scene.render.precision,
                       std::min(1.0, double(kNoiseProbeSide) / longest)};
    const Scene probe = withSettings(scene, s);
    NoiseProbe noise;
    noise.scale = double(std::max(probe.render.width, probe.render.height)) / longest;
    const double pixels = double(probe.render.width) * probe.render.height;
    for (int n = 2; n <= kNoiseProbeSamples; n *= 2) {
        RenderOptions options = oneShotOptions();
        options.adaptive = AdaptiveSampling{0.0, 255.0, n};
        // The first render checks the scene (it throws if it is invalid); on
        // a million spheres each check hashed every name again.
        options.sceneValidated = n > 2;
        const RenderResult r = render(probe, options, {}, stop);
        noise.mseAt[n] = r.adaptive ? r.adaptive->estimatedMse : 0.0;
        noise.rays += r.rays.total();
        if (n == 2) noise.raysPerSample = r.rays.total() / (2.0 * pixels);
    }
    return noise;
}

// The noise of `samples` a pixel in the probe: measured, or extrapolated on
// the slope between neighbouring counts (one sample: a pixel's centre, as
// the picture's first sample is, taken as the slope back from two).
double probeNoiseAt(const NoiseProbe& noise, int samples, double& slope) {
    const double last = noise.mseAt.rbegin()->second;
    const double beforeLast = std::next(noise.mseAt.rbegin())->second;
    slope = last > 0.0 && beforeLast > 0.0 ? std::log2(beforeLast / last) : 1.0;
    slope = std::clamp(slope, 0.5, 2.0);
    if (auto found = noise.mseAt.find(samples); found != noise.mseAt.end()) return found->second;
    if (samples < noise.mseAt.begin()->first) {
        const double two = noise.mseAt.at(2), four = noise.mseAt.at(4);
        const double back =
            two > 0.0 && four > 0.0 ? std::clamp(std::log2(two / four), 0.5, 2.0) : 1.0;
        return two * std::pow(2.0, back);
    }
    if (samples > noise.mseAt.rbegin()->first) {
        slope = std::min(slope, kSteepestLongRunSlope);
        return last * std::pow(double(noise.mseAt.rbegin()->first) / samples, slope);
    }
    // Between two powers of two: log-log between them.
    auto above = noise.mseAt.upper_bound(samples);
    auto below = std::prev(above);
    const double t =
        std::log2(double(samples) / below->first) / std::log2(double(above->first) / below->first);
    if (below->second <= 0.0 || above->second <= 0.0) return below->second;
    return below->second * std::pow(above->second / below->second, t);
}

}  // namespace

RenderPrediction predictRender(const Scene& scene, const StopPredicate& stop) {
    RenderPrediction p;
    const double pixels = double(scene.render.width) * scene.render.height;
    if (std::max(scene.render.width, scene.render.height) < kNoiseProbeSide / 2) {
        p.cannot = "the picture is smaller than a probe, which would cost more than rendering it";
        return p;
    }
    const auto start = std::chrono::steady_clock::now();
    // A stopped probe is an empty picture: what follows it means nothing.
    auto stopped = [&] {
        if (!stop || !stop()) return false;
        p.cannot = "stopped";
        return true;
    };
    // A 40 dB target only sets the probe's size (a quarter of the side).
    const QualityPlan plan =
        planQuality(scene, QualityTarget{"", 40.0, std::nullopt}, 1, scene.render.maxDepth, stop);
    if (stopped()) return p;
    const NoiseProbe noise = probeNoise(scene, stop);
    if (stopped()) return p;
    p.depthMse = plan.depthMse;
    p.precisionMse = plan.precisionMse;
    p.samplingMse = kNoiseCalibration *
                    probeNoiseAt(noise, scene.render.samplesPerPixel, p.samplingSlope) *
                    noise.scale;
    p.mseCodes2 = p.depthMse + p.precisionMse + p.samplingMse;
    p.psnrDb = psnrFromMse(p.mseCodes2);
    p.rays = noise.raysPerSample * pixels * scene.render.samplesPerPixel;
    p.seconds = predictSeconds(probeSpeed(scene, kSpeedProbePixels, stop), scene, p.rays);
    if (stopped()) return p;
    p.probeRays = plan.probeRays + noise.rays;
    p.probeSeconds = secondsSince(start);
    p.predicted = true;
    return p;
}

}  // namespace whitted
