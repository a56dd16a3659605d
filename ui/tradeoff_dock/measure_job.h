// The editor's Measure action: the whole speed/accuracy trade of the open
// scene (core/analysis/tradeoff.h: a reference render, then every point of a grid) on a
// thread of its own, so the editor stays responsive. Points reach the GUI as
// they are measured; Cancel stops within a tile row of work and keeps them.
#pragma once

#include <QObject>
#include <QString>

#include <atomic>
#include <thread>

#include "analysis/tradeoff.h"
#include "prediction/measure_results.h"

namespace whitted::ui {

// The grid Measure runs unless told otherwise: both scales a user is likely to
// preview at, samples up to 64, every depth to 8, both precisions, each point
// run once (more while it takes under 50 ms). docs/design/editor.md gives its
// duration on the seed scene.
TradeoffGrid editorMeasureGrid();
// Samples per pixel of the reference: four times the grid's most, so that
// its own noise adds about 6 % to the error of the 64-sample points (512
// would make that 2 %, for a reference twice as long).
inline constexpr int kEditorReferenceSamples = 256;

int gridPointCount(const TradeoffGrid& grid);

class MeasureJob : public QObject {
    Q_OBJECT
  public:
    MeasureJob(const Scene& scene, const TradeoffGrid& grid, int referenceSamples,
               QObject* parent = nullptr);
    ~MeasureJob() override;  // cancels and waits for the thread

    void start();
    // Asks the thread to stop; finished() follows with the points measured so far.
    void cancel() { cancelled_ = true; }
    int total() const { return total_; }

  signals:
    void referenceDone(double seconds);
    void pointMeasured(const whitted::TradeoffPoint& point, int done, int total);
    // Exactly once, also after a cancel; `error` is core's message when the run
    // failed, and then `results` holds what was measured before.
    void finished(const whitted::ui::MeasureResults& results, const QString& error);

  private:
    void run();

    Scene scene_;
    TradeoffGrid grid_;
    int referenceSamples_;
    int total_;
    std::atomic<bool> cancelled_{false};
    std::thread thread_;
};

}  // namespace whitted::ui

Q_DECLARE_METATYPE(whitted::TradeoffPoint)
Q_DECLARE_METATYPE(whitted::ui::MeasureResults)
