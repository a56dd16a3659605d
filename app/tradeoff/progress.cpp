#include "progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "base/elapsed.h"

namespace whitted::tradeoff {

double pointWork(const TradeoffSettings& settings) {
    return settings.samplesPerPixel * settings.resolutionScale * settings.resolutionScale;
}

double estimateGridSeconds(const TradeoffGrid& grid, const ReferenceRender& reference) {
    const RenderSettings& r = reference.scene.render;
    const double perSamplePixel =
        reference.seconds / (double(r.samplesPerPixel) * r.width * r.height);
    double total = 0.0;
    for (double scale : grid.scales)
        for (int samples : grid.samples) {
            const double once = perSamplePixel * samples * r.width * r.height * scale * scale;
            // Runs until minSeconds, at least minRuns and at most maxRuns times.
            const double runs = std::clamp(std::max(double(grid.minRuns), grid.minSeconds / once),
                                           1.0, double(std::max(1, grid.maxRuns)));
            total += once * std::ceil(runs) * grid.depths.size() * grid.precisions.size();
        }
    return total;
}

Progress::Progress(const TradeoffGrid& grid, bool tty)
    : tty_(tty), start_(std::chrono::steady_clock::now()) {
    for (double scale : grid.scales)
        for (int samples : grid.samples)
            totalWork_ += pointWork({samples, 0, Precision::Float, scale}) * grid.depths.size() *
                          grid.precisions.size();
}

void Progress::point(const TradeoffProgress& p) {
    const TradeoffPoint& last = *p.last;
    doneWork_ += pointWork(last.settings);
    const double elapsed = secondsSince(start_);
    // Points differ in cost by a factor of a thousand: the ETA extrapolates by
    // work done, not by points done.
    const double eta = doneWork_ > 0 ? elapsed * (totalWork_ - doneWork_) / doneWork_ : 0.0;
    char text[200];
    std::snprintf(text, sizeof text,
                  "[%3d/%3d] ETA %4.0f s | %3d spp, depth %d, %-6s x%.2g: %8.2f ms, %5.1f dB",
                  p.done, p.total, std::max(0.0, eta), last.settings.samplesPerPixel,
                  last.settings.maxDepth,
                  std::string(precisionName(last.settings.precision)).c_str(),
                  last.settings.resolutionScale, last.seconds * 1000, last.error.psnrSrgb8);
    if (tty_) {
        constexpr int kWidth = 28;
        const int filled = p.total ? kWidth * p.done / p.total : kWidth;
        std::fprintf(stderr, "\r[%s%s] %s", std::string(filled, '#').c_str(),
                     std::string(kWidth - filled, ' ').c_str(), text);
        if (p.done == p.total) std::fprintf(stderr, "\n");
    } else {
        std::fprintf(stderr, "%s\n", text);
    }
    std::fflush(stderr);
}

}  // namespace whitted::tradeoff
