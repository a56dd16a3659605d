#include "panels/preset_controls.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QWidget>

#include <cmath>

#include "analysis/render_presets.h"
#include "document/quality_choice.h"
#include "document/scene_document.h"
#include "document/settings_words.h"
#include "panels/number_field.h"
#include "prediction/render_record.h"

namespace whitted::ui {

namespace {

QString viewText(std::string_view s) {
    return QString::fromUtf8(s.data(), qsizetype(s.size()));
}

QString presetName(const RenderPreset& p) {
    return viewText(p.name);
}

void applyPreset(const RenderPreset& p, RenderSettings& r) {
    r.samplesPerPixel = p.samplesPerPixel;
    r.maxDepth = p.maxDepth;
    r.precision = p.precision;
}

// "Final (128 spp, depth 8, float)": what choosing it renders with "Render
// to" on the settings.
QString presetText(const RenderPreset& p) {
    return QObject::tr("%1 (%2)").arg(presetName(p),
                                      settingsText(p.samplesPerPixel, p.maxDepth, p.precision));
}

QLabel* makePredictionLabel(const QString& name) {
    auto* label = new QLabel;
    label->setObjectName(name);
    label->setWordWrap(true);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

}  // namespace

PresetControls::PresetControls(SceneDocument* doc, RenderRecord* record, QualityChoice* quality,
                               QFormLayout* form)
    : QObject(form->parentWidget()), doc_(doc), record_(record), quality_(quality) {
    combo_ = new QComboBox;
    combo_->setObjectName(QStringLiteral("renderPreset"));
    combo_->addItem(tr("Custom"));
    for (const RenderPreset& p : kRenderPresets) combo_->addItem(presetText(p));
    combo_->setToolTip(
        tr("Sets samples per pixel, max depth and precision in one step, and renders "
           "to the preset's quality"));
    // activated: only the user's choices, not the refreshes that follow edits.
    connect(combo_, &QComboBox::activated, this, &PresetControls::choose);

    time_ = makePredictionLabel(QStringLiteral("predictedTime"));
    time_->setToolTip(tr("How long a render with the current settings takes"));
    error_ = makePredictionLabel(QStringLiteral("predictedError"));
    error_->setToolTip(
        tr("Root-mean-square error of the 8-bit sRGB image against Measure's "
           "reference (in steps of 1/255), and its PSNR"));
    target_ = QualityChoice::makeComboBox(QStringLiteral("qualityTarget"), quality_->target());
    target_->setToolTip(
        tr("With a target, each render chooses its depth for the scene and samples each "
           "part of the picture until its estimated error is under the target (at most "
           "%1 samples per pixel); the status bar says what it chose and reached")
            .arg(kDefaultMaxSamples));
    connect(target_, &QComboBox::activated, this, &PresetControls::chooseTarget);

    form->insertRow(0, tr("Preset:"), combo_);
    form->insertRow(1, tr("Render to:"), target_);
    form->insertRow(2, tr("Predicted time:"), time_);
    form->insertRow(3, tr("Predicted error:"), error_);

    connect(doc_, &SceneDocument::sceneChanged, this, &PresetControls::refresh);
    connect(quality_, &QualityChoice::changed, this, &PresetControls::refresh);
    connect(quality_, &QualityChoice::reachedNoted, this, &PresetControls::refresh);
    connect(record_, &RenderRecord::changed, this, &PresetControls::refresh);
    refresh();
}

int PresetControls::shownPreset(const RenderSettings& settings,
                                const std::optional<QualityTarget>& target) {
    if (!target) return matchingPreset(settings);
    for (std::size_t i = 0; i < kRenderPresets.size(); ++i)
        if (kRenderPresets[i].name == target->name) return int(i);
    return -1;
}

int PresetControls::matchingPreset(const RenderSettings& settings) {
    for (std::size_t i = 0; i < kRenderPresets.size(); ++i) {
        RenderSettings preset = settings;
        applyPreset(kRenderPresets[i], preset);
        if (preset == settings) return int(i);
    }
    return -1;
}

QString PresetControls::timeText(const Prediction& p) {
    if (!p.seconds) return tr("unknown: %1").arg(p.timeSource);
    return tr("%1 (%2)").arg(secondsText(*p.seconds), p.timeSource);
}

QString PresetControls::errorText(const Prediction& p) {
    if (!p.rmseSrgb8) return p.errorSource;
    const QString psnr = std::isfinite(p.psnrSrgb8.value_or(0))
                             ? tr("PSNR %1 dB").arg(*p.psnrSrgb8, 0, 'f', 1)
                             : tr("identical");
    return tr("RMSE %1 of 255, %2 (%3)").arg(*p.rmseSrgb8, 0, 'f', 2).arg(psnr, p.errorSource);
}

QString PresetControls::targetTimeText(const TargetPrediction* p, const QString& reached) {
    const QString last =
        reached.isEmpty() ? QString() : tr("; the last one here took %1").arg(reached);
    if (!p)
        return tr("not predicted yet: each render to a target chooses its own depth and "
                  "samples, which the probes predict once edits pause%1")
            .arg(last);
    if (!p->predicted)
        return tr("not predicted: %1%2").arg(QString::fromStdString(p->cannot), last);
    return tr("about %1 (%2 of it choosing the settings): depth %3, %4 samples per pixel on "
              "average, from %5% of the picture's tiles rendered to the target%6")
        .arg(secondsText(p->seconds()), secondsText(p->planSeconds))
        .arg(p->plan.maxDepth)
        .arg(p->meanSamples, 0, 'f', 1)
        .arg(std::lround(100.0 * p->tilesShare))
        .arg(last);
}

QString PresetControls::targetErrorText(const TargetPrediction* p,
                                        const std::optional<QualityTarget>& target) {
    const QString aim = QualityChoice::describe(target);
    if (!p || !p->predicted)
        return tr("the target, %1; the status bar shows the render's estimate").arg(aim);
    const QString largest =
        target->largestCodes
            ? tr(", no pixel off by more than about %1 codes").arg(p->largestCodes, 0, 'f', 1)
            : QString();
    const QString predicted =
        tr("about %1 dB%2 (the target, %3)").arg(p->psnrDb, 0, 'f', 1).arg(largest, aim);
    // planQuality() found no depth that cuts off little enough: its words say by what.
    return p->plan.depthShort ? tr("%1; the plan says it may be missed").arg(predicted) : predicted;
}

void PresetControls::choose(int index) {
    if (index <= 0) {  // Custom: nothing to set, show what the settings match
        refresh();
        return;
    }
    QString error;
    if (!apply(doc_, quality_, kRenderPresets[std::size_t(index - 1)], &error))
        showRefusal(combo_, error);
    refresh();
}

void PresetControls::chooseTarget(int) {
    quality_->setTarget(QualityChoice::chosenIn(target_));
}

bool PresetControls::apply(SceneDocument* doc, QualityChoice* quality, const RenderPreset& preset,
                           QString* error) {
    const bool applied = doc->edit(
        tr("Apply %1 preset").arg(presetName(preset)),
        [&](Scene& s) { applyPreset(preset, s.render); }, error);
    if (applied && quality) quality->setTarget(qualityPreset(preset.name));
    return applied;
}

void PresetControls::refresh() {
    const Scene& scene = doc_->scene();
    const std::optional<QualityTarget>& target = quality_->target();
    refreshChoices(scene, target);
    const Prediction now = record_->predict(scene);
    refreshPrediction(scene, target, now);
    refreshTooltips(scene, now);
}

void PresetControls::refreshChoices(const Scene& scene,
                                    const std::optional<QualityTarget>& target) {
    {
        // While a target rules, the presets are targets: the scene's
        // samples and depth are not what the view renders ("Final (128 spp,
        // depth 8)" read as the picture's settings while it was rendered at
        // depth 6 with 2 to 128 samples a pixel).
        const QSignalBlocker block(combo_);
        for (std::size_t i = 0; i < kRenderPresets.size(); ++i) {
            const RenderPreset& preset = kRenderPresets[i];
            combo_->setItemText(
                int(i) + 1,
                target ? QualityChoice::describe(qualityPreset(preset.name)) : presetText(preset));
        }
        combo_->setCurrentIndex(shownPreset(scene.render, target) + 1);
    }
    {
        const QSignalBlocker block(target_);
        target_->setCurrentIndex(QualityChoice::indexOf(target));
    }
}

void PresetControls::refreshPrediction(const Scene& scene,
                                       const std::optional<QualityTarget>& target,
                                       const Prediction& now) {
    if (target) {
        const TargetPrediction* ahead = record_->targetPrediction(scene, *target);
        const QString reached = quality_->lastReached(target->name);
        time_->setText(targetTimeText(ahead, reached));
        error_->setText(targetErrorText(ahead, target));
    } else if (quality_->whitted1980()) {
        // Its rays follow the picture's edges: no probe or past render of the
        // settings speaks for them.
        const QString none =
            tr("none for Whitted 1980 sampling: the status bar says what each "
               "render took");
        time_->setText(none);
        error_->setText(none);
    } else {
        time_->setText(timeText(now));
        error_->setText(errorText(now));
    }
}

void PresetControls::refreshTooltips(const Scene& scene, const Prediction& now) {
    // Where the user hovers before choosing: the target the view will render
    // to, the probes' prediction of a render to it, what the last one here
    // took, and the prediction for the preset's own settings (what "Render
    // to: the settings" renders).
    for (std::size_t i = 0; i < kRenderPresets.size(); ++i) {
        const RenderPreset& preset = kRenderPresets[i];
        RenderSettings with = scene.render;
        applyPreset(preset, with);
        const Prediction p = record_->predict(scene, &with);
        const QString tip =
            tr("%1\nIts settings, when rendering to the samples per pixel and "
               "max depth set here:\nTime: %2\nError: %3")
                .arg(targetTip(scene, *qualityPreset(preset.name)), timeText(p), errorText(p));
        combo_->setItemData(int(i) + 1, tip, Qt::ToolTipRole);
    }
    // The same for "Render to": the settings, predicted also while a target
    // is chosen (probe_predictor.h), and each target.
    target_->setItemData(
        0,
        tr("Renders %1 samples per pixel to max depth %2 in %3, as set here.\n"
           "Time: %4\nError: %5")
            .arg(scene.render.samplesPerPixel)
            .arg(scene.render.maxDepth)
            .arg(viewText(precisionName(scene.render.precision)), timeText(now), errorText(now)),
        Qt::ToolTipRole);
    const std::vector<QualityTarget> targets = QualityChoice::offered();
    for (std::size_t i = 0; i < targets.size(); ++i)
        target_->setItemData(int(i) + 1, targetTip(scene, targets[i]), Qt::ToolTipRole);
}

QString PresetControls::targetTip(const Scene& scene, const QualityTarget& target) const {
    const TargetPrediction* ahead = record_->targetPrediction(scene, target);
    const QString reached = quality_->lastReached(target.name);
    return tr("Renders to %1, choosing the depth and samples for this scene.\n"
              "Time: %2\nError: %3\n%4")
        .arg(QualityChoice::describe(target), targetTimeText(ahead, QString()),
             targetErrorText(ahead, target),
             reached.isEmpty() ? tr("Not yet rendered to it on this scene: the status bar will "
                                    "show what it takes.")
                               : tr("The last render to it here: %1.").arg(reached));
}

}  // namespace whitted::ui
