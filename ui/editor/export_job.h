// File > Export Image: the dialog that asks for the settings, and the job that
// renders and writes the file on a thread of its own, so the editor stays
// responsive and the user can cancel.
#pragma once

#include <QDialog>
#include <QObject>
#include <QString>

#include <atomic>
#include <optional>
#include <thread>

#include "analysis/plan_memo.h"
#include "analysis/quality_target.h"
#include "scene/scene.h"

class QComboBox;
class QFormLayout;
class QLineEdit;
class QSpinBox;

namespace whitted::ui {

class ImageSizeFields;

struct ExportSettings {
    QString path;
    RenderSettings render;
    // 0: a still. N: a turntable of N frames, the eye turning once about
    // look_at, written as path's name with 0001 to N before the extension.
    int turntableFrames = 0;
    // Set: rendered to this quality (document/quality_choice.h), each frame
    // with the depth and samples chosen for it; render's samples and depth unused.
    std::optional<QualityTarget> quality;
};

class ExportDialog : public QDialog {
    Q_OBJECT
  public:
    // Starts from the scene's render settings, the editor's quality target
    // and a file name in `directory`.
    ExportDialog(const Scene& scene, const std::optional<QualityTarget>& quality,
                 const QString& directory, const QString& baseName, QWidget* parent = nullptr);
    ExportSettings settings() const;

  private:
    void addFileRows(QFormLayout* form, const QString& directory, const QString& baseName);
    void addRenderRows(QFormLayout* form, const RenderSettings& r,
                       const std::optional<QualityTarget>& quality);
    void addTurntableRow(QFormLayout* form);
    void browse();
    void formatChosen(int index);

    QLineEdit* path_;
    QComboBox* format_;
    ImageSizeFields* size_;
    QSpinBox *samples_, *depth_, *turntable_;
    QComboBox* precision_;
    QComboBox* quality_;
};

// Renders a scene with the given settings and writes it. Emits progress from
// the render thread (queued to the GUI) and finished() once, on success, on
// failure (with core's message) and on cancel. A cancelled or failed export
// leaves no file.
class ExportJob : public QObject {
    Q_OBJECT
  public:
    // A render to a quality takes its plan from `plans`, which must outlive
    // the job: at the view's size, the view's plan.
    ExportJob(const Scene& scene, const ExportSettings& settings, PlanMemo& plans,
              QObject* parent = nullptr);
    ~ExportJob() override;  // cancels and waits for the thread
    void start();
    void cancel() { cancelled_ = true; }

  signals:
    void progress(int percent);
    void finished(bool ok, const QString& message);

  private:
    // Renders and writes one image, frame `frame` of the turntable about
    // `camera` (0: a still); false, having emitted finished(), when
    // cancelled or failed.
    bool exportFrame(int frame, const Camera& camera, double& seconds);
    // What a still rendered to a quality chose and reached, for the message.
    QString qualityReached(const QualityPlan& plan, const AdaptiveOutcome& reached) const;

    Scene scene_;
    ExportSettings settings_;
    PlanMemo& plans_;
    std::atomic<bool> cancelled_{false};
    std::thread thread_;
    QString reached_;  // the last frame's qualityReached(), empty without a target
};

}  // namespace whitted::ui
