// The Render tab's predicted time against the editor's own render, in the
// editor itself: a MainWindow (offscreen unless QT_QPA_PLATFORM says
// otherwise) on each shipped scene and two generated
// fields, at 640x480, depth 5, float, and 8 and 32 samples a pixel. Each case
// is one edit, as a user makes it; the view renders it at once, in passes,
// while ProbePredictor's probes start 0.4 s later at a lower priority. The
// bench waits for both and prints the view's seconds (the status bar's)
// over the seconds the Render tab showed: the probes' for one pass, and
// the view's passes at its pace (RenderRecord::viewPace()) as it stood
// before this case, learnt on the cases before it (none before the first: the editor's
// start scene is its first render, which sets no pace). Then, with the
// editor idle, it renders the same scene in one pass (the faster of two):
// the prediction's own error, apart from what the view's passes and display
// add.
// Usage: bench_editor_prediction [WIDTH HEIGHT] (default 640 480). Prints a Markdown table.
#include <QApplication>
#include <QElapsedTimer>
#include <QSettings>
#include <QStandardPaths>
#include <QThread>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include "base/heap_reuse.h"
#include "bench_scenes.h"
#include "document/scene_document.h"
#include "editor/main_window.h"
#include "prediction/probe_predictor.h"
#include "prediction/render_record.h"

using namespace whitted;
using namespace whitted::ui;

namespace {

constexpr int kTimeoutMs = 120000;

// Runs the event loop until `done` or the timeout; false on the timeout.
template <typename Done>
bool waitFor(const Done& done) {
    QElapsedTimer clock;
    clock.start();
    while (!done()) {
        if (clock.elapsed() > kTimeoutMs) return false;
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
        QThread::msleep(2);
    }
    return true;
}

struct Case {
    double probes = 0.0;     // the probes' seconds for one pass
    double extra = 0.0;      // for the view's passes, at its pace before this case
    double predicted = 0.0;  // the Render tab's: the probes' and that
    double rendered = 0.0, onePass = 0.0;
};

// Sets the scene (as one edit) with `samples` a pixel and waits for the
// view's complete render of it and for the probes' prediction of it.
std::optional<Case> measure(MainWindow& window, Scene scene, int samples) {
    scene.render.samplesPerPixel = samples;
    scene.render.maxDepth = 5;
    std::optional<double> rendered;
    const QMetaObject::Connection seen =
        QObject::connect(&window, &MainWindow::frameShown, &window, [&](const RenderFrame& f) {
            if (f.renderComplete && f.settings == scene.render) rendered = f.seconds;
        });
    const bool edited =
        window.document()->edit(QStringLiteral("bench"), [&](Scene& s) { s = scene; });
    // Before this render and prediction pair up: the pace of the ones before.
    const ViewPace pace = window.renderRecord()->viewPace();
    const auto predicted = [&]() -> const ProbePrediction* {
        const ProbePrediction* p = window.renderRecord()->probePrediction();
        return p && p->scene.render == scene.render ? p : nullptr;
    };
    const bool done = edited && waitFor([&] { return rendered && predicted(); });
    QObject::disconnect(seen);
    if (!done || !predicted()->prediction.predicted) return std::nullopt;
    const double probes = predicted()->prediction.seconds;
    const double extra = viewExtraSeconds(scene.render, pace);
    return Case{probes, extra, probes + extra, *rendered, fasterOfTwo(scene).seconds};
}

}  // namespace

int main(int argc, char** argv) {
    whitted::reuseHeapForLargeBlocks();  // as the editor's main() does
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    QStandardPaths::setTestModeEnabled(true);  // no autosave or settings of the user's
    QApplication app(argc, argv);
    QApplication::setOrganizationName("WhittedBench");
    QApplication::setApplicationName("bench_editor_prediction");
    QSettings().clear();
    const int width = argc > 2 ? std::atoi(argv[1]) : 640;
    const int height = argc > 2 ? std::atoi(argv[2]) : 480;

    MainWindow window;
    window.resize(1200, 800);
    window.show();
    // As a user sees it first: the new scene rendered and predicted (the
    // view's first render, beside the window's first showing, sets no pace).
    bool startRendered = false;
    const QMetaObject::Connection start = QObject::connect(
        &window, &MainWindow::frameShown, &window,
        [&](const RenderFrame& f) { startRendered = startRendered || f.renderComplete; });
    if (!waitFor([&] { return startRendered && window.renderRecord()->probePrediction(); })) {
        std::fprintf(stderr,
                     "bench_editor_prediction: the first render or prediction never came\n");
        return 1;
    }
    QObject::disconnect(start);
    std::printf(
        "%dx%d, depth 5, float; the view's render (in passes, as the status bar times "
        "it) over the Render tab's prediction (the probes' for one pass, and the view's "
        "passes at its pace on its renders before); in brackets, one pass rendered "
        "alone over the probes' prediction\n\n",
        width, height);
    std::printf(
        "| scene | 8 spp: predicted (passes), rendered, ratio (one pass) | 32 spp "
        "|\n|---|---|---|\n");
    int within = 0, onePassWithin = 0, cases = 0;
    for (const NamedScene& n :
         benchScenes(width, height,
                     {generatedField(150, 31, 4.0, 10.0), generatedField(400, 57, 4.0, 10.0)})) {
        std::printf("| %s |", n.name.c_str());
        for (int samples : {8, 32}) {
            const std::optional<Case> c = measure(window, n.scene, samples);
            if (!c) {
                std::printf(" no prediction or render |");
                continue;
            }
            const double ratio = c->rendered / c->predicted;
            const double onePassRatio = c->onePass / c->probes;
            ++cases;
            within += std::fabs(ratio - 1.0) <= 0.25;
            onePassWithin += std::fabs(onePassRatio - 1.0) <= 0.25;
            std::printf(" %.3f s (+%.3f), %.3f s, %.2f (%.2f) |", c->predicted, c->extra,
                        c->rendered, ratio, onePassRatio);
        }
        std::printf("\n");
        std::fflush(stdout);
    }
    std::printf("\nwithin 25%%: %d of %d (one pass alone: %d)\n", within, cases, onePassWithin);
    return 0;
}
