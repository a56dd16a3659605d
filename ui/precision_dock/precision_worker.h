// The float-versus-double view's thread: compares a scene's float and double
// renders (core's comparePrecisions) away from the GUI thread.
//
// As RenderWorker does: request() hands over a scene snapshot, bumps a
// generation number and returns at once; the thread runs the newest request,
// whose stop predicate says yes as soon as a newer generation exists, and hands
// the result back through a queued signal that carries its generation, so the
// GUI can drop stale ones. cancel() bumps the generation without a new request.
// Its threads run at a lower priority (nice 10 on Linux).
#pragma once

#include <QImage>
#include <QObject>
#include <QSize>

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <thread>

#include "analysis/precision_compare.h"
#include "scene/scene.h"

namespace whitted::ui {

struct PrecisionResult {
    quint64 generation = 0;
    PrecisionComparison comparison;  // its heatMap moved into `heatMap` below
    QImage heatMap;                  // 8-bit sRGB, comparison.width x comparison.height
    double seconds = 0.0;            // the whole comparison, both renders included
};

class PrecisionWorker : public QObject {
    Q_OBJECT
  public:
    explicit PrecisionWorker(QObject* parent = nullptr);
    ~PrecisionWorker() override;  // stops the current comparison and joins the thread

    // Compares `scene` at `size` as soon as the current comparison has stopped;
    // returns the request's generation. Never blocks on the comparison.
    quint64 request(const Scene& scene, QSize size);
    // Stops the current comparison (its result never comes) and drops a waiting request.
    void cancel();
    quint64 latestGeneration() const { return generation_.load(); }

  signals:
    // Only finished comparisons: a stopped one sends nothing.
    void comparisonReady(const whitted::ui::PrecisionResult& result);

  private:
    struct Request {
        Scene scene;
        QSize size;
    };
    void run();

    std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<Request> pending_;  // guarded by mutex_
    bool quit_ = false;               // guarded by mutex_
    std::atomic<quint64> generation_{0};
    std::atomic<bool> quitting_{false};
    std::thread thread_;
};

}  // namespace whitted::ui

Q_DECLARE_METATYPE(whitted::ui::PrecisionResult)
