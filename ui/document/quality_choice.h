// Whether the editor renders to the scene's samples and depth or to a quality
// target: Draft, Preview or Final, each resolved per scene by
// planQuality() at every render. Chosen in the Render tab, by the presets
// (Ctrl+1 to Ctrl+3) and in the Export dialog. An editor setting like the
// view's camera, not part of the scene file (SPEC §4 has no such field), so
// choosing it is not an undo step; a new or opened scene keeps it.
#pragma once

#include <QObject>
#include <QString>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "analysis/quality_target.h"
#include "tracer/whitted1980_sampling.h"

class QComboBox;

namespace whitted::ui {

class QualityChoice : public QObject {
    Q_OBJECT
  public:
    explicit QualityChoice(QObject* parent = nullptr) : QObject(parent) {}

    // Unset: render the scene's samples per pixel and max depth.
    const std::optional<QualityTarget>& target() const { return target_; }
    // A target sets the sampler back to the scene's samples per pixel.
    void setTarget(std::optional<QualityTarget> target);
    // Set: the view samples as Whitted's 1980 paper does (corners, cut where
    // they differ) instead of the scene's samples per pixel; it leaves any
    // target, which chooses samples of its own.
    const std::optional<Whitted1980Sampling>& whitted1980() const { return whitted1980_; }
    void setWhitted1980(std::optional<Whitted1980Sampling> sampling);

    // "Final: 50 dB, no pixel off by more than 16 codes", or what no target means.
    static QString describe(const std::optional<QualityTarget>& target);
    // "1 sample per pixel", "16 samples per pixel", as the status bar says
    // it (Qt's "%n sample(s)" keeps the "(s)" where no translation is loaded).
    static QString samplesPerPixel(int samples);
    // "2 to 64 samples per pixel", or "1 sample per pixel" where every
    // tile stopped at one count (a Draft render that its centres met).
    static QString samplesTaken(const AdaptiveOutcome& reached);
    // "depth 6, 2 to 64 samples per pixel, about 51.2 dB": what a render to
    // the plan reached, as the export message and the presets' tooltips say it.
    static QString reachedText(const QualityPlan& plan, const AdaptiveOutcome& reached);
    // The targets the editor offers (Draft, Preview, Final), in the order of
    // its combo boxes, after "the settings".
    static std::vector<QualityTarget> offered();
    // A combo box of "the settings" and the offered targets, showing `shown`.
    static QComboBox* makeComboBox(const QString& objectName,
                                   const std::optional<QualityTarget>& shown);
    // The target a combo box from makeComboBox() shows.
    static std::optional<QualityTarget> chosenIn(const QComboBox* box);
    // Its index for `target` (0: the settings).
    static int indexOf(const std::optional<QualityTarget>& target);

    // What the view's last render to a named target reached on this scene
    // ("1.41 s, depth 6, 2 to 256 samples per pixel, about 51.1 dB"), for
    // the presets' tooltips; empty where none was rendered. Forgotten when
    // the scene is replaced.
    void noteReached(const std::string& targetName, const QString& text);
    QString lastReached(const std::string& targetName) const;
    void forgetReached();

  signals:
    void changed();       // the target or the sampler: the view renders again
    void reachedNoted();  // only what a render reached: nothing to render

  private:
    std::optional<QualityTarget> target_;
    std::optional<Whitted1980Sampling> whitted1980_;
    std::map<std::string, QString> reached_;
};

}  // namespace whitted::ui
