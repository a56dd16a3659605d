#include "tradeoff_dock/tradeoff_record.h"

#include <algorithm>
#include <utility>

namespace whitted::ui {

void TradeoffRecord::addRender(const EditorRender& render) {
    // One entry per settings: the newest time is the one the machine has now.
    std::erase_if(renders_, [&](const EditorRender& r) { return r.settings == render.settings; });
    renders_.push_back(render);
    if (renders_.size() > kMaxRenders) renders_.erase(renders_.begin());
    emit changed();
}

void TradeoffRecord::contentChanged() {
    bool marked = false;  // once per edit of many (a drag): nothing to refresh after the first
    for (EditorRender& r : renders_) marked = !std::exchange(r.earlierContent, true) || marked;
    if (marked) emit changed();
}

void TradeoffRecord::setMeasure(std::optional<MeasureResults> results) {
    measure_ = std::move(results);
    emit changed();
}

void TradeoffRecord::setProbePrediction(std::shared_ptr<const ProbePrediction> probe) {
    probe_ = std::move(probe);
    pace();
    emit changed();
}

const TargetPrediction* TradeoffRecord::targetPrediction(const Scene& scene,
                                                         const QualityTarget& target) const {
    if (!probe_ || !probe_->target || probe_->target->name != target.name ||
        probe_->target->psnrDb != target.psnrDb ||
        probe_->target->largestCodes != target.largestCodes ||
        !(probe_->scene.render == scene.render) || !sameSceneContent(probe_->scene, scene))
        return nullptr;
    return &probe_->toTarget;
}

void TradeoffRecord::addViewRender(const Scene& scene, double seconds) {
    if (!std::exchange(firstViewRenderSeen_, true)) return;
    lastView_ = ViewRender{scene, seconds};
    pace();
    emit changed();
}

// Whichever comes second, the render or the prediction, pairs them: a short
// render ends before the probes start, a long one after they are done.
void TradeoffRecord::pace() {
    if (!lastView_ || !probe_ || !probe_->prediction.predicted ||
        probe_->prediction.seconds <= 0.0 || !(probe_->scene.render == lastView_->scene.render) ||
        !sameSceneContent(probe_->scene, lastView_->scene))
        return;
    paces_.push_back((lastView_->seconds - probe_->prediction.seconds) /
                     pixelPasses(lastView_->scene.render));
    if (paces_.size() > kPaceRenders) paces_.pop_front();
    lastView_.reset();
}

ViewPace TradeoffRecord::viewPace() const {
    if (paces_.empty()) return {};
    std::vector<double> sorted(paces_.begin(), paces_.end());
    std::sort(sorted.begin(), sorted.end());
    const std::size_t n = sorted.size();
    const double median = n % 2 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2.0;
    // A render quicker than its prediction says the prediction erred, not
    // that its passes cost less than nothing.
    return {std::max(0.0, median), int(n)};
}

void TradeoffRecord::clear() {
    renders_.clear();
    measure_.reset();
    probe_.reset();
    lastView_.reset();
    emit changed();
}

}  // namespace whitted::ui
