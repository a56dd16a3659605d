// What the Render tab predicts for a scene's render settings: the time from
// throughput measured in the editor or by Measure, the error from Measure's
// grid. Every prediction names where its numbers come from, so the label never
// passes off an estimate as a measurement.
#pragma once

#include <QString>

#include <cstdint>
#include <optional>
#include <vector>

#include "prediction/measure_results.h"
#include "prediction/probe_predictor.h"
#include "scene/scene.h"

namespace whitted::ui {

// A render the editor finished: its settings, wall time and ray count.
struct EditorRender {
    RenderSettings settings;
    double seconds = 0.0;
    std::uint64_t rays = 0;
    // Of the scene before an edit: its time estimates, but does not measure,
    // a render of the scene now (RenderRecord::contentChanged()).
    bool earlierContent = false;
};

struct Prediction {
    std::optional<double> seconds;
    QString timeSource;  // "measured by Measure", "estimated from the last render …"
    std::optional<double> rmseSrgb8;
    std::optional<double> psnrSrgb8;
    QString errorSource;  // where the error comes from, or why there is none
};

// What the view's renders take beyond the probes' prediction of one pass of
// their rays: its preview and passes (each reads and writes the picture's
// sums, each ends with a frame the window shows, on the same cores), priced
// a pixel and a pass (at most 0.02 to 0.05 s a pass at 640x480; docs/design/quality-planning.md). A
// factor would not do: it was 1.1 to 1.5 on renders of a tenth of a second
// and 1.01 on one of nine. Measured in the editor, on its own renders: the
// median of the last few whose scene the probes predicted
// (RenderRecord::addViewRender()). Until one is, the median of the
// shipped and generated scenes' at 640x480 (bench_editor_prediction).
inline constexpr double kUnmeasuredSecondsAPixelPass = 22e-9;
struct ViewPace {
    double secondsAPixelPass = kUnmeasuredSecondsAPixelPass;
    int renders = 0;  // it was measured on
};

// Pixels times passes (passCount()) of a view's render of these settings:
// what its seconds beyond one pass grow with.
double pixelPasses(const RenderSettings& settings);

// The view's seconds beyond one pass, for a render of these settings.
double viewExtraSeconds(const RenderSettings& settings, ViewPace pace);

// Predicts time and error of rendering `scene` with `settings` (its own when
// not given; a preset's without a copy of the scene).
// `renders` is the editor's history, newest last; `measure` may be null.
//  - Both from Measure when its grid holds the settings at the scene's size.
//  - Otherwise the time from the editor's renders: the newest one with the
//    same settings, else one with the same depth and precision scaled by
//    pixels times samples, else the newest scaled the same way (rough).
//  - The error interpolated between Measure's neighbouring sample counts (log-
//    log, as error falls like a power of the samples).
//  - Where Measure does not cover the settings, the error and the rays from
//    `probe` (probe_predictor.h) when it was made for this very scene and
//    these settings; where no render at these settings gives the time, so
//    do the probes' timed renders, at the view's `pace`. Else no error, with the reason.
Prediction predictSettings(const Scene& scene, const std::vector<EditorRender>& renders,
                           const MeasureResults* measure, const RenderSettings* settings = nullptr,
                           const ProbePrediction* probe = nullptr, ViewPace pace = {});

}  // namespace whitted::ui
