// The "Float vs Double" dock: where the scene's float render differs from its
// double render, as a heat map (core/heat_map.h) and counts.
//
// It works only while shown: on showing, and after every change of the scene
// while shown (debounced, the delay restarting with each edit, so a drag
// compares once it pauses), it asks its PrecisionWorker for a comparison at a
// capped size. The GUI thread never waits for one; until the new result comes
// the old one stays on screen, marked as out of date.
#pragma once

#include <QLabel>
#include <QTimer>
#include <QWidget>

#include "precision_worker.h"

namespace whitted::ui {

class SceneDocument;
class HeatMapView;

class PrecisionView : public QWidget {
    Q_OBJECT
  public:
    explicit PrecisionView(SceneDocument* doc, QWidget* parent = nullptr);

    // Both renders are at the scene's aspect ratio, the long side at most this:
    // a comparison then takes tens of milliseconds for the example scenes.
    static constexpr int kMaxSide = 480;
    // Quiet time after the last edit before a comparison starts.
    static constexpr int kDebounceMs = 300;
    static QSize comparisonSize(const Scene& scene);

    // The result on screen; generation 0 before the first.
    const PrecisionResult& shownResult() const { return shown_; }

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
    void onResult(const PrecisionResult& result);

    SceneDocument* doc_;
    PrecisionWorker worker_;
    QTimer debounce_;
    bool dirty_ = true;      // the scene changed since the shown (or running) comparison
    bool inFlight_ = false;  // a request whose result has not come yet
    PrecisionResult shown_;
    HeatMapView* heatMap_;
    QLabel *status_, *over1_, *over2_, *largest_, *hit_, *shadow_, *tir_;
};

}  // namespace whitted::ui
