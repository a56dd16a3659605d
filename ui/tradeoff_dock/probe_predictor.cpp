#include "tradeoff_dock/probe_predictor.h"

#include <utility>

#include "base/thread_priority.h"

namespace whitted::ui {

ProbePredictor::ProbePredictor(PlanMemo& plans, QObject* parent)
    : QObject(parent),
      plans_(plans),
      requests_(
          RequestThread<ProbeRequest>::Policy::LatestWins,
          [this](ProbeRequest&& request, quint64 ticket) { predict(std::move(request), ticket); },
          lowerThisThreadsPriority) {
    qRegisterMetaType<std::shared_ptr<const whitted::ui::ProbePrediction>>();
    quiet_.setSingleShot(true);
    quiet_.setInterval(kQuietMs);
    connect(&quiet_, &QTimer::timeout, this, [this] { requests_.request(std::move(waiting_)); });
    connect(this, &ProbePredictor::posted, this, &ProbePredictor::deliver, Qt::QueuedConnection);
}

void ProbePredictor::sceneChanged(const Scene& scene, const std::optional<QualityTarget>& target) {
    waiting_ = {scene, target};
    quiet_.start();
}

void ProbePredictor::predict(ProbeRequest&& request, quint64 ticket) {
    auto result = std::make_shared<ProbePrediction>();
    const auto stale = [&] { return requests_.stale(ticket); };
    // As the view renders to a target (render_worker.cpp): at most
    // kDefaultMaxSamples a pixel, the depth chosen, and the same plan when
    // the view renders the same picture.
    if (request.target)
        result->toTarget = predictRenderTo(
            request.scene, *plans_.plan(request.scene, *request.target, kDefaultMaxSamples, stale),
            stale);
    else
        result->prediction = predictRender(request.scene, stale);
    result->scene = std::move(request.scene);
    result->target = std::move(request.target);
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
