// The float-versus-double view's thread: compares a scene's float and double
// renders (core's comparePrecisions) away from the GUI thread.
//
// As RenderWorker does (core/base/request_thread.h, the newest request wins):
// request() hands over a scene snapshot and returns at once with its
// generation; the thread runs the newest request, which stops as soon as a
// newer one exists, and hands the result back through a queued signal that
// carries its generation, so the GUI can drop stale ones. cancel() moves the
// generation on without a new request.
// Its threads run at a lower priority (nice 10 on Linux).
#pragma once

#include <QImage>
#include <QObject>
#include <QSize>

#include "analysis/precision_compare.h"
#include "base/request_thread.h"
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
    ~PrecisionWorker() override = default;  // stops the current comparison and joins the thread

    // Compares `scene` at `size` as soon as the current comparison has stopped;
    // returns the request's generation. Never blocks on the comparison.
    quint64 request(const Scene& scene, QSize size);
    // Stops the current comparison (its result never comes) and drops a waiting request.
    void cancel();
    quint64 latestGeneration() const { return requests_.latestTicket(); }

  signals:
    // Only finished comparisons: a stopped one sends nothing.
    void comparisonReady(const whitted::ui::PrecisionResult& result);

  private:
    struct Request {
        Scene scene;
        QSize size;
    };
    void compare(const Request& request, quint64 generation);

    RequestThread<Request> requests_;
};

}  // namespace whitted::ui

Q_DECLARE_METATYPE(whitted::ui::PrecisionResult)
