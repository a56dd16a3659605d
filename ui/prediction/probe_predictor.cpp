#include "prediction/probe_predictor.h"

#include <utility>

#include "base/thread_priority.h"
#include "document/quality_choice.h"

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

void ProbePredictor::sceneChanged(const Scene& scene, const std::optional<QualityTarget>& target,
                                  std::uint64_t contentRevision) {
    waiting_ = {scene, target, contentRevision};
    quiet_.start();
}

void ProbePredictor::predict(ProbeRequest&& request, quint64 ticket) {
    // What the view renders first. With a target, then the scene's own
    // settings: what "Render to" would go back to, and the samples and depth
    // a preset sets along with its target. Then the presets' other targets.
    std::vector<std::optional<QualityTarget>> targets{request.target};
    if (request.target) targets.push_back(std::nullopt);
    for (const QualityTarget& preset : QualityChoice::offered())
        if (request.target != preset) targets.push_back(preset);
    for (const std::optional<QualityTarget>& target : targets) {
        auto result = predictOne(request.scene, target, ticket);
        if (requests_.stale(ticket)) return;
        result->contentRevision = request.contentRevision;
        post(std::move(result));
    }
}

std::shared_ptr<ProbePrediction> ProbePredictor::predictOne(
    const Scene& scene, const std::optional<QualityTarget>& target, quint64 ticket) {
    auto result = std::make_shared<ProbePrediction>();
    const auto stale = [&] { return requests_.stale(ticket); };
    // As the view renders to a target (render_worker.cpp): at most
    // kDefaultMaxSamples a pixel, the depth chosen, and the same plan when
    // the view renders the same picture.
    if (target)
        result->toTarget =
            predictRenderTo(scene, *plans_.plan(scene, *target, kDefaultMaxSamples, stale), stale);
    else
        result->prediction = predictRender(scene, stale);
    result->scene = scene;
    result->target = target;
    return result;
}

void ProbePredictor::post(std::shared_ptr<const ProbePrediction> result) {
    {
        std::lock_guard lock(outboxMutex_);
        outbox_.push_back(std::move(result));
    }
    emit posted();
}

void ProbePredictor::deliver() {
    std::vector<std::shared_ptr<const ProbePrediction>> results;
    {
        std::lock_guard lock(outboxMutex_);
        results.swap(outbox_);
    }
    for (std::shared_ptr<const ProbePrediction>& r : results) emit predicted(std::move(r));
}

}  // namespace whitted::ui
