// What the editor knows of the open scene's renders: those it finished
// (their settings, times and rays), the view's pace beyond the probes'
// prediction, the probes' newest predictions (probe_predictor.h) and the last
// Measure run (times and errors). The Render tab's predictions and the
// Trade-off dock both read it.
#pragma once

#include <QObject>

#include <deque>
#include <memory>
#include <optional>
#include <vector>

#include "prediction/settings_prediction.h"

namespace whitted::ui {

class RenderRecord : public QObject {
    Q_OBJECT
  public:
    using QObject::QObject;

    // The newest render per settings, at most this many settings remembered.
    static constexpr std::size_t kMaxRenders = 32;

    void addRender(const EditorRender& render);
    // The scene's content changed (SceneDocument::contentRevision()): the
    // renders so far no longer measure it, though they still estimate it.
    void contentChanged();
    const std::vector<EditorRender>& renders() const { return renders_; }

    void setMeasure(std::optional<MeasureResults> results);
    const MeasureResults* measure() const { return measure_ ? &*measure_ : nullptr; }

    // A probe prediction (probe_predictor.h); it speaks for its scene only.
    // Of the settings: the newest. To a target: the newest scene's, one per target.
    void setProbePrediction(std::shared_ptr<const ProbePrediction> probe);
    // The newest prediction of a render to the scene's own settings.
    const ProbePrediction* probePrediction() const { return probe_.get(); }

    // The probes' prediction of a render of `scene` to `target`, once made
    // for that scene (but for the samples per pixel and depth, which a render
    // to a target chooses) and target; null until then.
    const TargetPrediction* targetPrediction(const Scene& scene, const QualityTarget& target) const;

    // The view's pace is the median of this many renders' (settings_prediction.h).
    static constexpr std::size_t kPaceRenders = 5;

    // The view finished rendering the document's content of revision
    // `contentRevision` (SceneDocument::contentRevision()) at `settings` in
    // `seconds`. Once the probes have predicted that very scene, the two give
    // the view's pace. Not the first render: it shares the cores with the
    // window's first showing (in bench_editor_prediction it took 1.4 times
    // the seed's renders after it). By revision, not a copy of the scene:
    // at a million spheres each finished render copied 100 MB in the
    // editor's thread.
    void addViewRender(std::uint64_t contentRevision, const RenderSettings& settings,
                       double seconds);
    ViewPace viewPace() const;

    // Forgets everything but the view's pace (a matter of the machine and the
    // editor, not of the scene): another scene was opened.
    void clear();

    Prediction predict(const Scene& scene, const RenderSettings* settings = nullptr) const {
        return predictSettings(scene, renders_, measure(), settings, probe_.get(), viewPace());
    }

  signals:
    void changed();

  private:
    struct ViewRender {
        std::uint64_t contentRevision = 0;
        RenderSettings settings;
        double seconds = 0.0;
    };
    // The view's newest render and the probes' newest prediction, once both
    // are of the same scene: what the render took beyond the prediction
    // joins paces_, once.
    void pace();

    std::vector<EditorRender> renders_;   // newest last
    std::optional<ViewRender> lastView_;  // not yet paced
    bool firstViewRenderSeen_ = false;
    // The view's seconds beyond the prediction, a pixel and a pass; newest last.
    std::deque<double> paces_;
    std::optional<MeasureResults> measure_;
    std::shared_ptr<const ProbePrediction> probe_;                   // of the settings
    std::vector<std::shared_ptr<const ProbePrediction>> toTargets_;  // of one scene
};

}  // namespace whitted::ui
