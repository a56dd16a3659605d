#include "tradeoff_dock/measure_job.h"

#include <chrono>
#include <exception>

#include "base/elapsed.h"

namespace whitted::ui {

TradeoffGrid editorMeasureGrid() {
    TradeoffGrid grid;
    grid.samples = {1, 2, 4, 8, 16, 32, 64};
    grid.depths = {0, 1, 2, 3, 4, 5, 6, 7, 8};
    grid.precisions = {Precision::Float, Precision::Double};
    grid.scales = {0.5, 1.0};
    // One run is enough where a render takes long enough to time; the quick
    // ones, whose single times are noisy, are run up to three times.
    grid.minRuns = 1;
    grid.maxRuns = 3;
    grid.minSeconds = 0.05;
    return grid;
}

int gridPointCount(const TradeoffGrid& grid) {
    return int(grid.samples.size() * grid.depths.size() * grid.precisions.size() *
               grid.scales.size());
}

MeasureJob::MeasureJob(const Scene& scene, const TradeoffGrid& grid, int referenceSamples,
                       QObject* parent)
    : QObject(parent),
      scene_(scene),
      grid_(grid),
      referenceSamples_(referenceSamples),
      total_(gridPointCount(grid)) {
    qRegisterMetaType<whitted::TradeoffPoint>();
    qRegisterMetaType<whitted::ui::MeasureResults>();
}

MeasureJob::~MeasureJob() {
    cancel();
    if (thread_.joinable()) thread_.join();
}

void MeasureJob::start() {
    thread_ = std::thread([this] { run(); });
}

void MeasureJob::run() {
    const auto start = std::chrono::steady_clock::now();
    const auto stop = [this] { return cancelled_.load(std::memory_order_relaxed); };
    MeasureResults results;
    results.scene = scene_;
    results.total = total_;
    results.referenceSamples = referenceSamples_;
    QString error;
    try {
        const ReferenceRender reference = renderReference(scene_, referenceSamples_, stop);
        results.referenceDepth = reference.scene.render.maxDepth;
        results.referenceSeconds = reference.seconds;
        if (!stop()) {
            emit referenceDone(reference.seconds);
            // The points are kept here as well as sent: a failure part-way
            // still returns the ones already measured.
            const auto onPoint = [&](const TradeoffProgress& p) {
                if (!p.last) return;
                results.points.push_back(*p.last);
                emit pointMeasured(*p.last, p.done, p.total);
            };
            results.points = runTradeoff(scene_, reference.image, grid_, onPoint, stop);
        }
    } catch (const std::exception& e) {
        error = QString::fromUtf8(e.what());
    }
    markParetoFront(results.points);
    results.cancelled = cancelled_.load();
    results.seconds = secondsSince(start);
    emit finished(results, error);
}

}  // namespace whitted::ui
