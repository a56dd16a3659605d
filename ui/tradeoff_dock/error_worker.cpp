#include "tradeoff_dock/error_worker.h"

#include <utility>

namespace whitted::ui {

ErrorWorker::ErrorWorker(QObject* parent)
    : QObject(parent),
      jobs_(RequestThread<ErrorJob>::Policy::EveryRequest,
            [this](ErrorJob&& job, quint64 ticket) { measure(job, ticket); }) {
    qRegisterMetaType<whitted::ErrorStats>();
}

void ErrorWorker::submit(ErrorJob job) {
    jobs_.request(std::move(job));
}

void ErrorWorker::clear() {
    jobs_.cancel();
}

void ErrorWorker::measure(const ErrorJob& job, quint64 ticket) {
    const ErrorStats error = measureError(*job.image, *job.reference);
    // A clear() that races past this check is caught by the GUI's own id
    // bookkeeping.
    if (!jobs_.stale(ticket)) emit measured(job.id, error);
}

}  // namespace whitted::ui
