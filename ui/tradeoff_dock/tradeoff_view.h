// The "Trade-off" dock: speed against accuracy for the open scene.
//
// Pin as Reference keeps the view's finished image (the complete frame of the
// current settings, never a preview) and its settings; from then on every
// finished render of a newer generation adds a point: its settings, its time,
// and its error against the pinned image (measureError on an ErrorWorker, off
// the GUI thread). Unpin drops the image and the points.
//
// A noisy image (fewer than kNoisyBelowSamples samples per pixel) is not
// pinned without a word: a message box offers to render a converged reference
// in the background (ReferenceJob, as Measure's reference) and pin that, or to
// pin the image anyway. A change of the scene other than its render settings
// (a sphere moved, the camera turned) makes the pin stale: the dock says so,
// and renders are not scored against it until it is pinned again (or the
// scene is undone back to the pinned one).
//
// Measure runs the whole trade-off of the scene (MeasureJob) in the background,
// with progress and Cancel; its points fill the plot as they come, the Pareto
// front ringed, and the finished (or cancelled) run goes to the RenderRecord
// that the Render tab predicts from.
#pragma once

#include <QTimer>
#include <QWidget>

#include <memory>
#include <optional>
#include <vector>

#include "tradeoff_dock/error_worker.h"
#include "tradeoff_dock/measure_job.h"
#include "tradeoff_dock/reference_job.h"
#include "tradeoff_dock/tradeoff_points.h"
#include "viewport/render_worker.h"

class QAction;
class QLabel;
class QProgressBar;
class QSplitter;
class QPushButton;
class QTableWidget;
class QTabWidget;

namespace whitted::ui {

class SceneDocument;
class RenderRecord;
class PlotWidget;

class TradeoffView : public QWidget {
    Q_OBJECT
  public:
    TradeoffView(SceneDocument* doc, RenderRecord* record, QWidget* parent = nullptr);
    ~TradeoffView() override;

    // Enabled once the current settings' render is complete.
    QAction* pinAction() const { return pin_; }
    QAction* unpinAction() const { return unpin_; }
    // Asks first (what it runs, how long it takes), then measures.
    QAction* measureAction() const { return measure_; }
    QAction* cancelMeasureAction() const { return cancel_; }

    // What Measure runs; the tests give a tiny grid.
    void setMeasureGrid(const TradeoffGrid& grid, int referenceSamples);
    const TradeoffGrid& measureGrid() const { return grid_; }
    // Starts measuring the current scene without asking; false if a run is going.
    bool startMeasure();
    bool isMeasuring() const { return job_ != nullptr; }

    // Fewer samples per pixel than this: jagged edges, worth a converged reference.
    static constexpr int kNoisyBelowSamples = 64;

    bool isPinned() const { return pinnedImage_ != nullptr; }
    // The scene has changed since the pin, other than in its render settings.
    bool isPinStale() const;
    bool isRenderingReference() const { return referenceJob_ != nullptr; }
    const RenderSettings& pinnedSettings() const { return pinnedSettings_; }
    std::shared_ptr<const Image> pinnedImage() const { return pinnedImage_; }
    const std::vector<PinnedPoint>& pinnedPoints() const { return points_; }
    // Measure's points on show: the running job's so far, else the last run's.
    const std::vector<TradeoffPoint>& measurePoints() const;
    const PlotWidget* plot() const { return plot_; }

    // Another scene was opened: unpin, stop measuring, forget.
    void sceneReplaced();

  public slots:
    // Every frame that reaches the render view (MainWindow::frameShown).
    void frameShown(const whitted::ui::RenderFrame& frame);

  protected:
    void resizeEvent(QResizeEvent* e) override;

  signals:
    // A pinned point's error came in (or it was skipped with a note).
    void pointMeasured(const whitted::ui::PinnedPoint& point);
    void measureProgress(int done, int total);
    void measureFinished(bool cancelled);

  private:
    // The constructor's parts, in order.
    void buildActions();
    void buildWidgets();
    void buildLayout();
    void connectUpdates();

    // tradeoff_view_pinning.cpp
    void pinCurrent();
    void offerConvergedReference(const RenderFrame& noisy);
    void startConvergedReference();
    void onReferenceRendered(const ConvergedReference& reference, const QString& error);
    void pin(std::shared_ptr<const Image> image, const RenderSettings& settings, double seconds,
             quint64 generation, const Scene& scene);
    void scoreFrame(const RenderFrame& frame);
    void stopReference();
    void unpinAll();
    void onErrorMeasured(quint64 id, const ErrorStats& error);
    void updatePinStatus();

    // tradeoff_view_measure.cpp
    void confirmMeasure();
    void onMeasurePoint(const TradeoffPoint& point, int done, int total);
    void onMeasureFinished(const MeasureResults& results, const QString& error);
    void updateMeasureStatus();

    void updateActions();
    void refreshPlot();
    void arrangeSplit();
    bool plotTabbed() const;
    void setPlotTabbed(bool tabbed);
    void showTable(QTableWidget* table);  // or the plot, where it is a tab of its own
    // "640 × 480": the pin's and Measure's texts both show sizes.
    static QString sizeText(int w, int h);

    SceneDocument* doc_;
    RenderRecord* record_;
    ErrorWorker errors_;

    std::optional<RenderFrame> complete_;  // the current settings' finished frame, if any
    std::shared_ptr<const Image> pinnedImage_;
    RenderSettings pinnedSettings_;
    double pinnedSeconds_ = 0.0;
    quint64 pinnedGeneration_ = 0;
    Scene pinnedScene_;  // what the pinned image shows
    std::unique_ptr<ReferenceJob> referenceJob_;
    QString referenceError_;  // the last converged reference's failure, if it failed
    std::vector<PinnedPoint> points_;
    quint64 nextId_ = 1;

    TradeoffGrid grid_;
    int referenceSamples_;
    std::unique_ptr<MeasureJob> job_;
    std::vector<TradeoffPoint> live_;  // the running job's points so far
    QString measureError_;             // the last run's failure, if it failed
    QTimer liveRefresh_;               // coalesces the plot updates of a running Measure

    QAction *pin_, *unpin_, *measure_, *cancel_;
    QLabel* pinStatus_;
    QLabel* pinStale_;  // shown while the pin is stale
    QLabel* measureStatus_;
    QProgressBar* progress_;
    QPushButton* cancelButton_;
    QSplitter* split_;         // the plot and the tables
    bool splitMoved_ = false;  // by the user: then only a turn resets it
    QTimer arrange_;           // arrangeSplit() after the columns' widths changed
    QWidget* plotBox_;         // the plot and its note: in the split, or a tab beside the tables
    PlotWidget* plot_;
    QLabel* plotNote_;
    QTabWidget* tabs_;
    QTableWidget* pinnedTable_;
    QTableWidget* measureTable_;
};

}  // namespace whitted::ui
