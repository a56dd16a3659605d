#include "precision_dock/precision_worker.h"

#include <chrono>
#include <utility>

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

#include "viewport/image_convert.h"

namespace whitted::ui {

namespace {

// The comparison is a side view: when it shares the cores with the main render
// or the GUI, they should win. Nice 10 gives it about a tenth of a core's share
// against them; 19 would starve it whenever anything else runs (a build). On
// Linux a nice value belongs to a thread, and the threads it creates (render()'s
// pool) inherit it.
constexpr int kNice = 10;

void lowerThisThreadsPriority() {
#ifdef __linux__
    setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), kNice);
#endif
}

}  // namespace

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
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    emit comparisonReady(result);
}

}  // namespace whitted::ui
