// The Render tab's presets (core/analysis/render_presets.h) and the time and error
// predicted for the current settings (settings_prediction.h).
//
// Choosing Draft, Preview or Final sets samples per pixel, max depth and
// precision as one undoable edit, and makes the preset's quality the target
// the editor renders to ("Render to", document/quality_choice.h): depth and
// samples are then chosen for the scene at each render. The combo box shows
// the preset the scene's settings match, else Custom; while a target rules,
// its items name their targets and it shows the one that rules. The
// predictions are for the settings; they follow every edit, every finished
// render and every Measure result, and say where they come from, or that a
// target has none.
// Each preset's tooltip names the target it renders to, the prediction of a
// render to it, what the view's last render to it on this scene took
// (QualityChoice::lastReached()), and the prediction for its settings. The
// items of "Render to" say the same of each target, and of the settings.
#pragma once

#include <QObject>

#include <optional>

#include "analysis/render_presets.h"
#include "analysis/target_prediction.h"
#include "scene/scene.h"

class QComboBox;
class QFormLayout;
class QLabel;

namespace whitted::ui {

class QualityChoice;
class SceneDocument;
class RenderRecord;
struct Prediction;

class PresetControls : public QObject {
    Q_OBJECT
  public:
    // Inserts its rows at the top of `form`; lives as long as the form's widget.
    PresetControls(SceneDocument* doc, RenderRecord* record, QualityChoice* quality,
                   QFormLayout* form);

    // Sets the preset's samples, depth and precision as one undoable edit and
    // its quality as the target (what choosing it does); false with the
    // reason if the edit is refused, and then the target stays as it was.
    static bool apply(SceneDocument* doc, QualityChoice* quality, const RenderPreset& preset,
                      QString* error = nullptr);
    // Index into kRenderPresets of the preset `settings` match, or -1.
    static int matchingPreset(const RenderSettings& settings);
    // The preset the combo box shows: while `target` rules, the one named
    // like it (its items then name their targets), else matchingPreset().
    static int shownPreset(const RenderSettings& settings,
                           const std::optional<QualityTarget>& target);
    // "1.2 s" and "RMSE 2.3 of 255, PSNR 41 dB" with their sources, as the labels show them.
    static QString timeText(const Prediction& p);
    static QString errorText(const Prediction& p);
    // The same for a render to `target`, from the probes' prediction of it
    // (null: not made yet) and what the last render to it here took.
    static QString targetTimeText(const TargetPrediction* p, const QString& reached);
    static QString targetErrorText(const TargetPrediction* p,
                                   const std::optional<QualityTarget>& target);

  private:
    void choose(int index);
    void chooseTarget(int index);
    void refresh();
    void refreshChoices(const Scene& scene, const std::optional<QualityTarget>& target);
    void refreshPrediction(const Scene& scene, const std::optional<QualityTarget>& target,
                           const Prediction& now);
    void refreshTooltips(const Scene& scene, const Prediction& now);
    // A preset's or "Render to"'s tooltip for `target`: what it is, the
    // probes' prediction of a render to it, and what the last one here took.
    QString targetTip(const Scene& scene, const QualityTarget& target) const;

    SceneDocument* doc_;
    RenderRecord* record_;
    QualityChoice* quality_;
    QComboBox* combo_;
    QComboBox* target_;
    QLabel* time_;
    QLabel* error_;
};

}  // namespace whitted::ui
