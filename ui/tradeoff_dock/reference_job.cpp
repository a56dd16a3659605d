#include "tradeoff_dock/reference_job.h"

#include <exception>

#include "analysis/tradeoff.h"

namespace whitted::ui {

ReferenceJob::ReferenceJob(const Scene& scene, int samples, QObject* parent)
    : QObject(parent), scene_(scene), samples_(samples) {
    qRegisterMetaType<whitted::ui::ConvergedReference>();
}

ReferenceJob::~ReferenceJob() {
    cancelled_ = true;
    if (thread_.joinable()) thread_.join();
}

void ReferenceJob::start() {
    thread_ = std::thread([this] { run(); });
}

void ReferenceJob::run() {
    const auto stop = [this] { return cancelled_.load(std::memory_order_relaxed); };
    ConvergedReference out;
    QString error;
    try {
        ReferenceRender reference = renderReference(scene_, samples_, stop);
        if (stop()) return;  // its image is incomplete, and nobody waits for it
        out.settings = reference.scene.render;
        out.seconds = reference.seconds;
        out.image = std::make_shared<const Image>(std::move(reference.image));
    } catch (const std::exception& e) {
        error = QString::fromUtf8(e.what());
    }
    emit finished(out, error);
}

}  // namespace whitted::ui
