// The "Precision Check" dock: where the scene's float render differs from its
// double render, as a heat map (core/image/heat_map.h) and counts.
//
// It works only while shown: on showing, and after every change of the scene
// while shown (debounced, the delay restarting with each edit, so a drag
// compares once it pauses), it asks its PrecisionWorker for a comparison at
// preview size. The GUI thread never waits for one; until the new result comes
// the old one stays on screen, marked as out of date.
//
// It never takes cores from the main render: a comparison starts only once
// the main render of the same scene is complete, and a new edit stops a
// running one; its threads run at a lower priority besides
// (PrecisionWorker). So mainFrameShown must receive the main render's frames:
// after a scene change, nothing is compared until a complete one comes.
#pragma once

#include <QLabel>
#include <QTimer>
#include <QWidget>

#include "precision_dock/precision_worker.h"
#include "viewport/render_worker.h"

namespace whitted::ui {

class SceneDocument;
class HeatMapView;

class PrecisionView : public QWidget {
    Q_OBJECT
  public:
    explicit PrecisionView(SceneDocument* doc, QWidget* parent = nullptr);

    // Both renders are at the scene's aspect ratio, the long side at most this
    // (preview size): a comparison costs two renders of a quarter of the seed's
    // 640 x 480 pixels, float and double, at the scene's samples and depth.
    static constexpr int kMaxSide = 320;
    // Quiet time after the last edit before a comparison starts.
    static constexpr int kDebounceMs = 300;
    static QSize comparisonSize(const Scene& scene);

    // The result on screen; generation 0 before the first.
    const PrecisionResult& shownResult() const { return shown_; }

  public slots:
    // Every frame that reaches the render view (MainWindow::frameShown).
    void mainFrameShown(const whitted::ui::RenderFrame& frame);

  signals:
    void comparisonStarted(quint64 generation);
    // A current (not stale) result reached the heat map and the labels.
    void comparisonShown(const whitted::ui::PrecisionResult& result);

  protected:
    void showEvent(QShowEvent*) override;
    void hideEvent(QHideEvent*) override;

  private:
    void sceneChanged();
    void start();
    void startWhenMainRenderDone();
    void onResult(const PrecisionResult& result);

    SceneDocument* doc_;
    PrecisionWorker worker_;
    QTimer debounce_;
    bool dirty_ = true;               // the scene changed since the shown (or running) comparison
    bool inFlight_ = false;           // a request whose result has not come yet
    bool mainRenderRunning_ = false;  // the main render of the current scene is unfinished
    bool waitingForMain_ = false;     // a comparison is due once the main render is complete
    PrecisionResult shown_;
    HeatMapView* heatMap_;
    QLabel *intro_, *status_, *over1_, *over2_, *largest_, *hit_, *shadow_, *tir_;
};

}  // namespace whitted::ui
