// Errors of finished renders against the pinned image (core's measureError),
// computed on a thread of their own: at 640 × 480 one takes tens of
// milliseconds (an sRGB encode per channel), at 4K the better part of a second.
//
// Jobs run in the order given, each exactly once (core/base/request_thread.h,
// every request); a result comes back through a queued signal with the job's
// id. clear() drops the waiting jobs and makes the running one's result be
// dropped too (after Unpin nothing may come back).
#pragma once

#include <QObject>

#include <memory>

#include "base/request_thread.h"
#include "image/image.h"
#include "image/image_error.h"

namespace whitted::ui {

struct ErrorJob {
    quint64 id = 0;
    std::shared_ptr<const Image> image;
    std::shared_ptr<const Image> reference;
};

class ErrorWorker : public QObject {
    Q_OBJECT
  public:
    explicit ErrorWorker(QObject* parent = nullptr);
    ~ErrorWorker() override = default;  // finishes the running job and joins the thread

    void submit(ErrorJob job);
    void clear();

  signals:
    void measured(quint64 id, const whitted::ErrorStats& error);

  private:
    void measure(const ErrorJob& job, quint64 ticket);

    RequestThread<ErrorJob> jobs_;
};

}  // namespace whitted::ui

Q_DECLARE_METATYPE(whitted::ErrorStats)
