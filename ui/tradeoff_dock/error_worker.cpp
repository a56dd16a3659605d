#include "tradeoff_dock/error_worker.h"

#include <utility>

namespace whitted::ui {

ErrorWorker::ErrorWorker(QObject* parent) : QObject(parent) {
    qRegisterMetaType<whitted::ErrorStats>();
    thread_ = std::thread([this] { run(); });
}

ErrorWorker::~ErrorWorker() {
    {
        std::lock_guard lock(mutex_);
        quit_ = true;
    }
    wake_.notify_one();
    thread_.join();
}

void ErrorWorker::submit(ErrorJob job) {
    {
        std::lock_guard lock(mutex_);
        queue_.push_back(std::move(job));
    }
    wake_.notify_one();
}

void ErrorWorker::clear() {
    std::lock_guard lock(mutex_);
    queue_.clear();
    ++epoch_;
}

void ErrorWorker::run() {
    for (;;) {
        ErrorJob job;
        quint64 epoch;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [this] { return quit_ || !queue_.empty(); });
            if (quit_) return;
            job = std::move(queue_.front());
            queue_.pop_front();
            epoch = epoch_.load();
        }
        const ErrorStats error = measureError(*job.image, *job.reference);
        // Not under the lock: emitting posts an event, but a clear() that
        // races past this check is caught by the GUI's own id bookkeeping.
        if (epoch == epoch_.load()) emit measured(job.id, error);
    }
}

}  // namespace whitted::ui
