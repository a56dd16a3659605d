// What the editor knows about the speed/accuracy trade of the open scene: the
// renders it finished (their times) and the last Measure run (times and
// errors). The Render tab's predictions and the Trade-off dock both read it.
#pragma once

#include <QObject>

#include <memory>
#include <optional>
#include <vector>

#include "tradeoff_dock/settings_prediction.h"

namespace whitted::ui {

class TradeoffRecord : public QObject {
    Q_OBJECT
  public:
    using QObject::QObject;

    // The newest render per settings, at most this many settings remembered.
    static constexpr std::size_t kMaxRenders = 32;

    void addRender(const EditorRender& render);
    const std::vector<EditorRender>& renders() const { return renders_; }

    void setMeasure(std::optional<MeasureResults> results);
    const MeasureResults* measure() const { return measure_ ? &*measure_ : nullptr; }

    // The newest probe prediction (probe_predictor.h); it speaks for its scene only.
    void setProbePrediction(std::shared_ptr<const ProbePrediction> probe);
    const ProbePrediction* probePrediction() const { return probe_.get(); }

    // Forgets everything: another scene was opened.
    void clear();

    Prediction predict(const Scene& scene, const RenderSettings* settings = nullptr) const {
        return predictSettings(scene, renders_, measure(), settings, probe_.get());
    }

  signals:
    void changed();

  private:
    std::vector<EditorRender> renders_;  // newest last
    std::optional<MeasureResults> measure_;
    std::shared_ptr<const ProbePrediction> probe_;
};

}  // namespace whitted::ui
