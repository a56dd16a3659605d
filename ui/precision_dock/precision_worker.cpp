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

PrecisionWorker::PrecisionWorker(QObject* parent) : QObject(parent) {
    qRegisterMetaType<whitted::ui::PrecisionResult>();
    thread_ = std::thread([this] { run(); });
}

PrecisionWorker::~PrecisionWorker() {
    {
        std::lock_guard lock(mutex_);
        quit_ = true;
    }
    quitting_ = true;
    wake_.notify_one();
    thread_.join();
}

quint64 PrecisionWorker::request(const Scene& scene, QSize size) {
    quint64 generation;
    {
        // Only the copy of the scene happens under the lock.
        std::lock_guard lock(mutex_);
        pending_ = Request{scene, size};
        generation = ++generation_;
    }
    wake_.notify_one();
    return generation;
}

void PrecisionWorker::cancel() {
    std::lock_guard lock(mutex_);
    pending_.reset();
    ++generation_;
}

void PrecisionWorker::run() {
    lowerThisThreadsPriority();
    for (;;) {
        Request request;
        quint64 generation;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [this] { return quit_ || pending_.has_value(); });
            if (quit_) return;
            request = std::move(*pending_);
            pending_.reset();
            generation = generation_.load();
        }
        const auto start = std::chrono::steady_clock::now();
        const auto stop = [&] {
            return quitting_.load(std::memory_order_relaxed) ||
                   generation_.load(std::memory_order_relaxed) != generation;
        };
        PrecisionResult result;
        result.comparison =
            comparePrecisions(request.scene, request.size.width(), request.size.height(), stop);
        if (result.comparison.stopped) continue;  // superseded or cancelled
        result.generation = generation;
        result.heatMap = toQImage(result.comparison.heatMap);
        result.comparison.heatMap = Image();
        result.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        emit comparisonReady(result);
    }
}

}  // namespace whitted::ui
