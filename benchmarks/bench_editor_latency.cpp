// The editor's latency (the speed check): from a property change to
// (a) the first preview frame and (b) the complete full-resolution one-sample
// pass reaching the GUI thread, through the real RenderWorker thread and its
// queued signals. The seed scene at 1280x720, all cores.
//
// Each repetition alternates the blue ball's radius between two values (so no
// render can be reused), calls RenderWorker::request() as the editor does on an
// edit, and waits in the event loop until that render is complete before the
// next one. Usage: bench_editor_latency [REPETITIONS] (default 30).
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTimer>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "scene/scene_io.h"
#include "viewport/render_worker.h"

namespace {

using Clock = std::chrono::steady_clock;
constexpr double kPreviewTargetMs = 20.0;
constexpr double kFullPassTargetMs = 60.0;

struct Stats {
    double median, min, max;
};

Stats stats(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    const double median = n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
    return {median, v.front(), v.back()};
}

}  // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    const int repetitions = argc > 1 ? std::max(1, std::atoi(argv[1])) : 30;
    constexpr int kWarmUp = 3;  // thread pool start-up, first page faults

    whitted::Scene scene = whitted::loadScene(WHITTED_SCENES_DIR "/seed.json");
    scene.render.width = 1280;
    scene.render.height = 720;

    whitted::PlanMemo plans;
    whitted::ui::RenderWorker worker(plans);
    std::vector<double> previewMs, fullPassMs, completeMs;
    std::vector<double> previewWorkerMs,
        fullPassWorkerMs;  // frame.seconds: since the worker began the render
    quint64 generation = 0;
    Clock::time_point requested;
    bool sawPreview = false, sawFullPass = false;
    int previewIncomplete = 0;

    int run = 0;
    auto next = [&] {
        if (run == repetitions + kWarmUp) {
            app.quit();
            return;
        }
        scene.spheres[0].radius = run % 2 ? 0.6 : 0.61;  // the property change
        sawPreview = sawFullPass = false;
        requested = Clock::now();
        generation = worker.request(std::make_shared<const whitted::Scene>(scene));
    };

    // Same thread as `app`: frames arrive through queued connections, as in the editor.
    QObject receiver;
    QObject::connect(
        &worker, &whitted::ui::RenderWorker::frameReady, &receiver,
        [&](const whitted::ui::RenderFrame& f) {
            if (f.generation != generation) return;
            const double ms =
                std::chrono::duration<double, std::milli>(Clock::now() - requested).count();
            const bool measured = run >= kWarmUp;
            if (f.preview && !sawPreview) {
                sawPreview = true;
                if (measured) {
                    previewMs.push_back(ms);
                    previewWorkerMs.push_back(f.seconds * 1e3);
                    previewIncomplete += !f.passComplete;
                }
            }
            // The one-sample pass: pass 1 (after the preview). With one
            // sample per pixel it is also the last, whose frame is the
            // render-complete one.
            if (!f.preview && f.passComplete && f.pass == 1 && !sawFullPass) {
                sawFullPass = true;
                if (measured) {
                    fullPassMs.push_back(ms);
                    fullPassWorkerMs.push_back(f.seconds * 1e3);
                }
            }
            if (f.renderComplete) {
                if (measured) completeMs.push_back(ms);
                if (!sawPreview || !sawFullPass) {  // the medians would cover fewer runs
                    std::fprintf(stderr,
                                 "bench_editor_latency: run %d: render complete without a %s "
                                 "frame\n",
                                 run, sawPreview ? "full-pass" : "preview");
                    std::exit(1);
                }
                ++run;
                // Let the machine settle between repetitions.
                QTimer::singleShot(50, &receiver, next);
            }
        });
    QTimer::singleShot(0, &receiver, next);
    app.exec();

    if (previewMs.empty() || fullPassMs.empty()) {
        std::fprintf(stderr, "no frames measured\n");
        return 1;
    }
    const Stats p = stats(previewMs), f = stats(fullPassMs), c = stats(completeMs);
    std::printf("seed scene 1280x720, %d repetitions (+%d warm-up), %d render threads\n",
                repetitions, kWarmUp, whitted::resolveThreadCount(0));
    std::printf(
        "first preview frame:    median %6.1f ms  (min %6.1f, max %6.1f)  target %2.0f ms: "
        "%.2fx%s\n",
        p.median, p.min, p.max, kPreviewTargetMs, p.median / kPreviewTargetMs,
        previewIncomplete ? " (some previews sent before their pass was complete)" : "");
    std::printf(
        "full-resolution pass:   median %6.1f ms  (min %6.1f, max %6.1f)  target %2.0f ms: %.2fx\n",
        f.median, f.min, f.max, kFullPassTargetMs, f.median / kFullPassTargetMs);
    std::printf(
        "  of which in the worker (RenderFrame::seconds, medians): preview %.1f ms, full pass %.1f "
        "ms\n",
        stats(previewWorkerMs).median, stats(fullPassWorkerMs).median);
    std::printf("render complete frame:  median %6.1f ms  (min %6.1f, max %6.1f)\n", c.median,
                c.min, c.max);
    std::printf("(ratio = median / target; at most 1.00 meets the target)\n");
    return 0;
}
