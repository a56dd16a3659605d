#include "precision_dock/precision_worker.h"

#include <chrono>
#include <utility>

#include "base/elapsed.h"
#include "base/thread_priority.h"
#include "viewport/image_convert.h"

namespace whitted::ui {

// The comparison is a side view: the main render and the GUI should win.
PrecisionWorker::PrecisionWorker(QObject* parent)
    : QObject(parent),
      requests_(
          RequestThread<Request>::Policy::LatestWins,
          [this](Request&& request, quint64 generation) { compare(request, generation); },
          lowerThisThreadsPriority) {
    qRegisterMetaType<whitted::ui::PrecisionResult>();
}

quint64 PrecisionWorker::request(const Scene& scene, QSize size) {
    return requests_.request({scene, size});
}

void PrecisionWorker::cancel() {
    requests_.cancel();
}

void PrecisionWorker::compare(const Request& request, quint64 generation) {
    const auto start = std::chrono::steady_clock::now();
    const auto stop = [&] { return requests_.stale(generation); };
    PrecisionResult result;
    result.comparison =
        comparePrecisions(request.scene, request.size.width(), request.size.height(), stop);
    if (result.comparison.stopped) return;  // superseded or cancelled
    result.generation = generation;
    result.heatMap = toQImage(result.comparison.heatMap);
    result.comparison.heatMap = Image();
    result.seconds = secondsSince(start);
    emit comparisonReady(result);
}

}  // namespace whitted::ui
