#include "prediction/render_record.h"

#include <algorithm>
#include <utility>

#include "analysis/quality_target.h"

namespace whitted::ui {

void RenderRecord::addRender(const EditorRender& render) {
    // One entry per settings: the newest time is the one the machine has now.
    std::erase_if(renders_, [&](const EditorRender& r) { return r.settings == render.settings; });
    renders_.push_back(render);
    if (renders_.size() > kMaxRenders) renders_.erase(renders_.begin());
    emit changed();
}

void RenderRecord::contentChanged() {
    bool marked = false;  // once per edit of many (a drag): nothing to refresh after the first
    for (EditorRender& r : renders_) marked = !std::exchange(r.earlierContent, true) || marked;
    if (marked) emit changed();
}

void RenderRecord::setMeasure(std::optional<MeasureResults> results) {
    measure_ = std::move(results);
    emit changed();
}

void RenderRecord::setProbePrediction(std::shared_ptr<const ProbePrediction> probe) {
    if (!probe->target) {
        probe_ = std::move(probe);
        pace();
    } else {
        // A render to a target chooses its own samples and depth (plannedAlike).
        std::erase_if(toTargets_, [&](const auto& p) {
            return p->target == probe->target || !plannedAlike(p->scene, probe->scene);
        });
        toTargets_.push_back(std::move(probe));
    }
    emit changed();
}

const TargetPrediction* RenderRecord::targetPrediction(const Scene& scene,
                                                       const QualityTarget& target) const {
    for (const auto& p : toTargets_)
        if (p->target == target && plannedAlike(p->scene, scene)) return &p->toTarget;
    return nullptr;
}

void RenderRecord::addViewRender(std::uint64_t contentRevision, const RenderSettings& settings,
                                 double seconds) {
    if (!std::exchange(firstViewRenderSeen_, true)) return;
    lastView_ = ViewRender{contentRevision, settings, seconds};
    pace();
    emit changed();
}

// Whichever comes second, the render or the prediction, pairs them: a short
// render ends before the probes start, a long one after they are done.
void RenderRecord::pace() {
    if (!lastView_ || !probe_ || !probe_->prediction.predicted ||
        probe_->prediction.seconds <= 0.0 ||
        probe_->contentRevision != lastView_->contentRevision ||
        !(probe_->scene.render == lastView_->settings))
        return;
    paces_.push_back((lastView_->seconds - probe_->prediction.seconds) /
                     pixelPasses(lastView_->settings));
    if (paces_.size() > kPaceRenders) paces_.pop_front();
    lastView_.reset();
}

ViewPace RenderRecord::viewPace() const {
    if (paces_.empty()) return {};
    std::vector<double> sorted(paces_.begin(), paces_.end());
    std::sort(sorted.begin(), sorted.end());
    const std::size_t n = sorted.size();
    const double median = n % 2 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2.0;
    // A render quicker than its prediction says the prediction erred, not
    // that its passes cost less than nothing.
    return {std::max(0.0, median), int(n)};
}

void RenderRecord::clear() {
    renders_.clear();
    measure_.reset();
    probe_.reset();
    toTargets_.clear();
    lastView_.reset();
    emit changed();
}

}  // namespace whitted::ui
