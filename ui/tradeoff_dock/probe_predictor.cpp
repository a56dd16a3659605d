#include "tradeoff_dock/probe_predictor.h"

#include <utility>

#include "base/thread_priority.h"

namespace whitted::ui {

ProbePredictor::ProbePredictor(QObject* parent)
    : QObject(parent),
      requests_(
          RequestThread<Scene>::Policy::LatestWins,
          [this](Scene&& scene, quint64 ticket) { predict(std::move(scene), ticket); },
          lowerThisThreadsPriority) {
    qRegisterMetaType<std::shared_ptr<const whitted::ui::ProbePrediction>>();
    quiet_.setSingleShot(true);
    quiet_.setInterval(kQuietMs);
    connect(&quiet_, &QTimer::timeout, this, [this] { requests_.request(std::move(waiting_)); });
    connect(this, &ProbePredictor::posted, this, &ProbePredictor::deliver, Qt::QueuedConnection);
}

void ProbePredictor::sceneChanged(const Scene& scene) {
    waiting_ = scene;
    quiet_.start();
}

void ProbePredictor::predict(Scene&& scene, quint64 ticket) {
    auto result = std::make_shared<ProbePrediction>();
    result->prediction = predictRender(scene, [&] { return requests_.stale(ticket); });
    result->scene = std::move(scene);
    if (requests_.stale(ticket)) return;
    {
        std::lock_guard lock(outboxMutex_);
        outbox_ = std::move(result);
    }
    emit posted();
}

void ProbePredictor::deliver() {
    std::shared_ptr<const ProbePrediction> result;
    {
        std::lock_guard lock(outboxMutex_);
        result = std::move(outbox_);
    }
    if (result) emit predicted(std::move(result));
}

}  // namespace whitted::ui
