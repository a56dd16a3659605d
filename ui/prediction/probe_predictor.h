// The Render tab's predictions for a scene never measured:
// core's predictRender() (or, when the view renders to a target,
// predictRenderTo()) on a thread of its own, a moment after the last
// edit (it renders small probes of the scene, a few tenths of a second on a
// glass field, and would only compete with the view's render during a drag).
// Its thread runs at a lower priority (base/thread_priority.h): the probes
// then wait while the view renders instead of slowing it, and their figures,
// CPU time (analysis/speed_probe.h), do not mind the wait.
// After what the view renders (and, when that is a target, the scene's own
// settings), it predicts renders to the presets' other targets for their
// tooltips, each plan then kept for the view should the user choose that
// preset (PlanMemo).
// The newest scene wins (core/base/request_thread.h); each result comes back
// with the scene it was made for, through an outbox under a mutex of our own
// (as RenderWorker's frames do: ThreadSanitizer cannot see Qt's event queue
// hand a shared_ptr over, and reported the hand-over as a race).
#pragma once

#include <QObject>
#include <QTimer>

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "analysis/plan_memo.h"
#include "analysis/render_prediction.h"
#include "analysis/target_prediction.h"
#include "base/request_thread.h"
#include "scene/scene.h"

namespace whitted::ui {

struct ProbeRequest {
    Scene scene;
    std::optional<QualityTarget> target;  // set: a render to it, not to the settings
    std::uint64_t contentRevision = 0;    // the document's, for the scene
};

struct ProbePrediction {
    Scene scene;                          // what was predicted: its content and render settings
    std::uint64_t contentRevision = 0;    // the document's when it was asked for
    RenderPrediction prediction;          // of the settings, when there is no target
    std::optional<QualityTarget> target;  // set: a render to it was predicted instead
    TargetPrediction toTarget;
};

class ProbePredictor : public QObject {
    Q_OBJECT
  public:
    // A prediction to a target takes its plan from `plans` (shared with the
    // view's render), which must outlive the predictor.
    explicit ProbePredictor(PlanMemo& plans, QObject* parent = nullptr);
    ~ProbePredictor() override = default;  // finishes the running prediction and joins

    // How long after the last edit the prediction starts.
    static constexpr int kQuietMs = 400;

    // Predicts a render of `scene`, to `target` if set (then to its own
    // settings too), then to each preset's target, once edits have paused
    // for kQuietMs.
    // `contentRevision` is the document's (SceneDocument::contentRevision()).
    void sceneChanged(const Scene& scene, const std::optional<QualityTarget>& target,
                      std::uint64_t contentRevision = 0);

  signals:
    // In the GUI thread.
    void predicted(std::shared_ptr<const whitted::ui::ProbePrediction> result);
    // From the prediction thread: a result is waiting in the outbox.
    void posted();

  private:
    void predict(ProbeRequest&& request, quint64 ticket);
    std::shared_ptr<ProbePrediction> predictOne(const Scene& scene,
                                                const std::optional<QualityTarget>& target,
                                                quint64 ticket);
    void post(std::shared_ptr<const ProbePrediction> result);
    void deliver();  // GUI thread: takes the results and emits predicted() for each

    std::mutex outboxMutex_;
    std::vector<std::shared_ptr<const ProbePrediction>> outbox_;  // guarded by outboxMutex_

    PlanMemo& plans_;
    ProbeRequest waiting_;
    QTimer quiet_;
    RequestThread<ProbeRequest> requests_;
};

}  // namespace whitted::ui

Q_DECLARE_METATYPE(std::shared_ptr<const whitted::ui::ProbePrediction>)
