#include "tradeoff_dock/tradeoff_record.h"

#include <algorithm>

namespace whitted::ui {

void TradeoffRecord::addRender(const EditorRender& render) {
    // One entry per settings: the newest time is the one the machine has now.
    std::erase_if(renders_, [&](const EditorRender& r) { return r.settings == render.settings; });
    renders_.push_back(render);
    if (renders_.size() > kMaxRenders) renders_.erase(renders_.begin());
    emit changed();
}

void TradeoffRecord::setMeasure(std::optional<MeasureResults> results) {
    measure_ = std::move(results);
    emit changed();
}

void TradeoffRecord::setProbePrediction(std::shared_ptr<const ProbePrediction> probe) {
    probe_ = std::move(probe);
    emit changed();
}

void TradeoffRecord::clear() {
    renders_.clear();
    measure_.reset();
    probe_.reset();
    emit changed();
}

}  // namespace whitted::ui
