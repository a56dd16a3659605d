// The editor with a scene of 100,000 spheres (issue 6): how long the file
// takes to load and to open, how long an edit takes, what undo costs in
// memory, and when the first frames arrive. Prints its figures; not a test.
//   build/bin/bench_big_scene [SPHERES]   (default 100000)
#include <sys/resource.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QTemporaryDir>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "big_scene.h"
#include "main_window.h"
#include "scene_io.h"

namespace {

using whitted::Scene;

long maxRssKb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    const int count = argc > 1 ? std::atoi(argv[1]) : 100000;
    QTemporaryDir dir;
    const QString file = dir.filePath("big.json");
    whitted::saveScene(whitted::bench::bigScene(count), file.toStdString());
    std::printf("scene: %d spheres, %.1f MB\n", count + 1,
                double(QFileInfo(file).size()) / (1 << 20));

    QElapsedTimer t;
    t.start();
    const Scene loaded = whitted::loadScene(file.toStdString());
    std::printf("loadScene:            %7.0f ms\n", double(t.nsecsElapsed()) / 1e6);

    whitted::ui::MainWindow window;
    window.show();
    QElapsedTimer first;
    double preview = -1, fullPass = -1;
    int completeFrames = 0, previewFrames = 0;
    QObject::connect(&window, &whitted::ui::MainWindow::frameShown,
                     [&](const whitted::ui::RenderFrame& f) {
                         const double ms = double(first.nsecsElapsed()) / 1e6;
                         if (f.preview && preview < 0) preview = ms;
                         if (!f.preview && f.passComplete && fullPass < 0) fullPass = ms;
                         completeFrames += f.renderComplete;
                         previewFrames += f.preview;
                     });
    t.restart();
    first.start();
    if (!window.openFile(file)) return 1;
    std::printf("MainWindow::openFile: %7.0f ms\n", double(t.nsecsElapsed()) / 1e6);

    // The event loop while the worker renders: the longest single turn.
    double worstTurn = 0;
    QElapsedTimer spell;
    spell.start();
    while (spell.elapsed() < 3000 && preview < 0) {
        t.restart();
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        worstTurn = std::max(worstTurn, double(t.nsecsElapsed()) / 1e6);
    }
    std::printf("first preview frame:  %7.0f ms after opening (%s)\n", preview,
                preview < 0 ? "not within 3 s" : "shown");
    std::printf("longest event-loop turn while rendering: %.0f ms\n", worstTurn);

    // An edit as the user makes one, once the last render is complete: from
    // the edit to its first preview frame on screen.
    std::vector<double> editToPreview;
    for (int i = 0; i < 12; ++i) {
        const int complete = completeFrames;
        while (completeFrames == complete && spell.elapsed() < 120000)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        const int previews = previewFrames;
        t.restart();
        window.document()->edit("move",
                                [i](Scene& s) { s.spheres[7].center.y += i % 2 ? 0.1 : -0.1; });
        while (previewFrames == previews && spell.elapsed() < 120000)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 1);
        editToPreview.push_back(double(t.nsecsElapsed()) / 1e6);
    }
    std::printf("edit to its first preview on screen: median %.0f ms, slowest %.0f ms over 12\n",
                median(editToPreview),
                *std::max_element(editToPreview.begin(), editToPreview.end()));

    const long rssBefore = maxRssKb();
    std::vector<double> edits;
    for (int i = 0; i < 200; ++i) {
        t.restart();
        window.document()->edit("radius", [i](Scene& s) { s.spheres[i].radius = 0.2; });
        edits.push_back(double(t.nsecsElapsed()) / 1e6);
        QCoreApplication::processEvents();
    }
    std::printf("edit (copy, validate, undo delta): median %.0f ms, slowest %.0f ms over 200\n",
                median(edits), *std::max_element(edits.begin(), edits.end()));
    std::printf("peak memory: %.0f MB before the edits, %.0f MB after 200 (undo keeps deltas)\n",
                rssBefore / 1024.0, maxRssKb() / 1024.0);
    return 0;
}
