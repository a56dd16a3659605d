// The Render tab's predictions for a scene never measured (issue 15, item 3):
// core's predictRender() on a thread of its own, a moment after the last
// edit (it renders small probes of the scene, a few tenths of a second on a
// glass field, and would only compete with the view's render during a drag).
// The newest scene wins (core/base/request_thread.h); a result comes back
// through a queued signal with the scene it was made for.
#pragma once

#include <QObject>
#include <QTimer>

#include <memory>

#include "analysis/render_prediction.h"
#include "base/request_thread.h"
#include "scene/scene.h"

namespace whitted::ui {

struct ProbePrediction {
    Scene scene;  // what was predicted: its content and render settings
    RenderPrediction prediction;
};

class ProbePredictor : public QObject {
    Q_OBJECT
  public:
    explicit ProbePredictor(QObject* parent = nullptr);
    ~ProbePredictor() override = default;  // finishes the running prediction and joins

    // How long after the last edit the prediction starts.
    static constexpr int kQuietMs = 400;

    // Predicts `scene` once edits have paused for kQuietMs.
    void sceneChanged(const Scene& scene);

  signals:
    void predicted(std::shared_ptr<const whitted::ui::ProbePrediction> result);

  private:
    void predict(Scene&& scene, quint64 ticket);

    Scene waiting_;
    QTimer quiet_;
    RequestThread<Scene> requests_;
};

}  // namespace whitted::ui

Q_DECLARE_METATYPE(std::shared_ptr<const whitted::ui::ProbePrediction>)
