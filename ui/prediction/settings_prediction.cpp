#include "prediction/settings_prediction.h"

#include <QObject>

#include <algorithm>
#include <cmath>

#include "document/settings_words.h"
#include "image/image_error.h"
#include "tracer/renderer.h"

namespace whitted::ui {

namespace {

// Pixels times samples: what a render's time grows with at fixed depth and precision.
double work(const RenderSettings& r) {
    return double(r.width) * double(r.height) * double(r.samplesPerPixel);
}

// The probes' error and rays for these settings, when they were made for them.
const RenderPrediction* probeFor(const Scene& scene, const RenderSettings& want,
                                 const ProbePrediction* probe) {
    if (!probe || probe->target || !(probe->scene.render == want) ||
        !sameSceneContent(scene, probe->scene))
        return nullptr;
    return &probe->prediction;
}

void errorFromProbe(const RenderPrediction& r, Prediction& p) {
    if (!r.predicted) {
        p.errorSource = QObject::tr("cannot predict: %1").arg(QString::fromStdString(r.cannot));
        return;
    }
    p.rmseSrgb8 = std::sqrt(r.mseCodes2);
    p.psnrSrgb8 = r.psnrDb;
    p.errorSource = QObject::tr("predicted from small probe renders of this scene");
}

// The probes' seconds: their rays at the speed their timed renders showed for
// these samples, depth, precision and picture size (speed_probe.h), and the
// view's passes at its pace.
bool timeFromProbe(const RenderPrediction& r, const RenderSettings& want, ViewPace pace,
                   Prediction& p) {
    if (!r.predicted || r.seconds <= 0) return false;
    const double extra = viewExtraSeconds(want, pace);
    p.seconds = r.seconds + extra;
    p.timeSource = QObject::tr("predicted from small timed probe renders: %1 Mrays at %2 Mrays/s")
                       .arg(r.rays / 1e6, 0, 'f', 1)
                       .arg(r.rays / r.seconds / 1e6, 0, 'f', 1);
    const QString passes = QObject::tr("%1 s for the view's %2 passes and frames")
                               .arg(extra, 0, 'g', 2)
                               .arg(passCount(want));
    if (pace.renders == 0)
        p.timeSource += QObject::tr(", and about %1 (not yet measured here)").arg(passes);
    else if (pace.renders == 1)
        p.timeSource += QObject::tr(", and %1 (as its last render)").arg(passes);
    else
        p.timeSource +=
            QObject::tr(", and %1 (as its last %2 renders)").arg(passes).arg(pace.renders);
    return true;
}

void timeFromRenders(const RenderSettings& want, const std::vector<EditorRender>& renders,
                     const RenderPrediction* probe, ViewPace pace, Prediction& p) {
    for (auto r = renders.rbegin(); r != renders.rend(); ++r)
        if (r->settings == want && !r->earlierContent) {
            p.seconds = r->seconds;
            p.timeSource = QObject::tr("measured: the last render at these settings");
            return;
        }
    if (probe && timeFromProbe(*probe, want, pace, p)) return;
    if (renders.empty()) {
        p.timeSource = QObject::tr("no render has finished yet");
        return;
    }
    // Rays per second stay put while depth and precision do; the ray count
    // grows with pixels times samples.
    auto scaled = [&](const EditorRender& r, const QString& source) {
        p.seconds = r.seconds * work(want) / work(r.settings);
        const double mrays = r.seconds > 0 ? double(r.rays) / r.seconds / 1e6 : 0.0;
        p.timeSource = source.arg(settingsText(r.settings)).arg(mrays, 0, 'f', 1);
    };
    for (auto r = renders.rbegin(); r != renders.rend(); ++r)
        if (r->settings.maxDepth == want.maxDepth && r->settings.precision == want.precision) {
            scaled(*r, QObject::tr("estimated from the last render at %1 (%2 Mrays/s)"));
            return;
        }
    scaled(renders.back(), QObject::tr("rough estimate from the last render at %1 (%2 Mrays/s); "
                                       "depth and precision change the rays and their speed"));
}

// The points of Measure's grid at the settings' depth, precision and size,
// by sample count.
std::vector<const TradeoffPoint*> samplesLine(const MeasureResults& m, const RenderSettings& r) {
    std::vector<const TradeoffPoint*> line;
    for (const TradeoffPoint& p : m.points)
        if (p.settings.maxDepth == r.maxDepth && p.settings.precision == r.precision &&
            p.width == r.width && p.height == r.height)
            line.push_back(&p);
    std::sort(line.begin(), line.end(), [](auto* a, auto* b) {
        return a->settings.samplesPerPixel < b->settings.samplesPerPixel;
    });
    return line;
}

enum class Coverage { None, Interpolated, Exact };

// Fills error and time from Measure; with no cover, the reason in errorSource.
Coverage fromMeasure(const MeasureResults& m, const RenderSettings& want, Prediction& p) {
    const auto line = samplesLine(m, want);
    if (line.empty()) {
        p.errorSource = QObject::tr("Measure has no point at depth %1, %2, %3 × %4")
                            .arg(want.maxDepth)
                            .arg(precisionText(want.precision))
                            .arg(want.width)
                            .arg(want.height);
        return Coverage::None;
    }
    const int spp = want.samplesPerPixel;
    const auto upper = std::find_if(line.begin(), line.end(),
                                    [&](auto* q) { return q->settings.samplesPerPixel >= spp; });
    if (upper != line.end() && (*upper)->settings.samplesPerPixel == spp) {
        p.rmseSrgb8 = (*upper)->error.rmseSrgb8;
        p.psnrSrgb8 = (*upper)->error.psnrSrgb8;
        p.errorSource = QObject::tr("measured by Measure");
        p.seconds = (*upper)->seconds;
        p.timeSource = QObject::tr("measured by Measure");
        return Coverage::Exact;
    }
    if (upper == line.end() || upper == line.begin()) {
        p.errorSource = QObject::tr("outside Measure's grid (%1 to %2 spp at this depth)")
                            .arg(line.front()->settings.samplesPerPixel)
                            .arg(line.back()->settings.samplesPerPixel);
        return Coverage::None;
    }
    const TradeoffPoint& lo = **(upper - 1);
    const TradeoffPoint& hi = **upper;
    const double s0 = lo.settings.samplesPerPixel, s1 = hi.settings.samplesPerPixel;
    const double t = std::log(spp / s0) / std::log(s1 / s0);
    const double e0 = lo.error.rmseSrgb8, e1 = hi.error.rmseSrgb8;
    const double e = e0 > 0 && e1 > 0 ? std::exp(std::log(e0) + t * (std::log(e1) - std::log(e0)))
                                      : e0 + t * (e1 - e0);
    p.rmseSrgb8 = e;
    p.psnrSrgb8 = psnrFromMse(e * e);
    p.errorSource = QObject::tr("interpolated from Measure between %1 and %2 spp").arg(s0).arg(s1);
    // Time grows with the samples, not with their logarithm.
    p.seconds = lo.seconds + (spp - s0) / (s1 - s0) * (hi.seconds - lo.seconds);
    p.timeSource = p.errorSource;
    return Coverage::Interpolated;
}

}  // namespace

double pixelPasses(const RenderSettings& settings) {
    return double(settings.width) * settings.height * passCount(settings);
}

double viewExtraSeconds(const RenderSettings& settings, ViewPace pace) {
    return pace.secondsAPixelPass * pixelPasses(settings);
}

Prediction predictSettings(const Scene& scene, const std::vector<EditorRender>& renders,
                           const MeasureResults* measure, const RenderSettings* settings,
                           const ProbePrediction* probe, ViewPace pace) {
    Prediction p;
    const RenderSettings& want = settings ? *settings : scene.render;
    const RenderPrediction* probed = probeFor(scene, want, probe);
    Coverage c = Coverage::None;
    if (!measure) {
        p.errorSource = QObject::tr("Measure gives an error prediction");
    } else if (!sameSceneContent(scene, measure->scene)) {
        p.errorSource = QObject::tr(
            "the scene changed since Measure: measure again for an "
            "error prediction");
    } else {
        c = fromMeasure(*measure, want, p);
        // An interpolated time yields to the editor's own renders, which come
        // from the very settings or a plain scaling of them.
        if (c == Coverage::Exact || (c == Coverage::Interpolated && renders.empty())) return p;
        p.seconds.reset();
    }
    if (c == Coverage::None && probed) errorFromProbe(*probed, p);
    timeFromRenders(want, renders, probed, pace, p);
    return p;
}

}  // namespace whitted::ui
