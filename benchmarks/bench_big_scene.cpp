// The editor with a scene of 100,000 spheres: how long the file
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
#include <cstdlib>
#include <vector>

#include "base/heap_reuse.h"
#include "big_scene.h"
#include "editor/main_window.h"
#include "scene/scene_io.h"

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
    whitted::reuseHeapForLargeBlocks();  // as the editor's main() does
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
    double preview = -1, fullPass = -1, opened = -1;
    double previewRender = 0;  // the last preview frame's RenderFrame::seconds, in ms
    int previewFrames = 0;
    bool rendering = true;  // the last frame shown was not a render's last
    QObject::connect(&window, &whitted::ui::MainWindow::frameShown,
                     [&](const whitted::ui::RenderFrame& f) {
                         const double ms = double(first.nsecsElapsed()) / 1e6;
                         if (f.preview && preview < 0) preview = ms;
                         if (f.preview) previewRender = f.seconds * 1e3;
                         // The file's, not the scene the window opened with.
                         if (!f.preview && f.passComplete && fullPass < 0 && opened >= 0)
                             fullPass = ms;
                         rendering = !f.renderComplete;
                         previewFrames += f.preview;
                     });
    t.restart();
    first.start();
    if (!window.openFile(file)) return 1;
    opened = double(first.nsecsElapsed()) / 1e6;
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
    while (fullPass < 0 && spell.elapsed() < 20000)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    if (fullPass < 0) {
        std::fprintf(stderr, "bench_big_scene: no full picture of the file within 20 s\n");
        return 1;
    }
    std::printf("the file's first full picture: %.0f ms from the start of opening\n", fullPass);

    // Runs the event loop until `done`; a frame that never comes ends the
    // benchmark with an error rather than with figures of nothing.
    auto waitFor = [](const char* what, auto done) {
        QElapsedTimer waited;
        waited.start();
        while (!done()) {
            if (waited.elapsed() > 20000) {
                std::fprintf(stderr, "bench_big_scene: no %s within 20 s\n", what);
                std::exit(1);
            }
            QCoreApplication::processEvents(QEventLoop::AllEvents, 1);
        }
    };

    // An edit as the user makes one, once the last render is complete: from
    // the edit to its first preview frame on screen. Moving one sphere, as the
    // sphere page does (SceneDocument::editItem), and as a whole-scene edit().
    whitted::ui::SceneDocument* doc = window.document();
    auto editToPreview = [&](const char* what, auto move) {
        std::vector<double> ms, render;
        for (int i = 0; i < 12; ++i) {
            waitFor("complete picture", [&] { return !rendering; });
            const int previews = previewFrames;
            t.restart();
            move(i % 2 ? 0.1 : -0.1);
            waitFor("preview after an edit", [&] { return previewFrames > previews; });
            ms.push_back(double(t.nsecsElapsed()) / 1e6);
            render.push_back(previewRender);
        }
        std::printf(
            "%s to its first preview on screen: median %.1f ms, fastest %.1f ms, "
            "slowest %.1f ms over 12 (median %.1f ms of it in the render thread)\n",
            what, median(ms), *std::min_element(ms.begin(), ms.end()),
            *std::max_element(ms.begin(), ms.end()), median(render));
    };
    editToPreview("item edit ", [&](double dy) {
        doc->editItem<whitted::Sphere>(7, "move", [dy](whitted::Sphere& s) { s.center.y += dy; });
    });
    editToPreview("scene edit", [&](double dy) {
        doc->edit("move", [dy](Scene& s) { s.spheres[7].center.y += dy; });
    });

    // The document's part alone (copy, compare, validate, undo step), and what
    // its listeners do on sceneChanged (the render request among them).
    const long rssBefore = maxRssKb();
    auto editsAlone = [&](const char* what, auto change) {
        std::vector<double> ms;
        for (int i = 0; i < 200; ++i) {
            t.restart();
            change(i);
            ms.push_back(double(t.nsecsElapsed()) / 1e6);
            QCoreApplication::processEvents();
        }
        std::printf(
            "%s (document and listeners): median %.2f ms, fastest %.2f ms, slowest "
            "%.2f ms over 200\n",
            what, median(ms), *std::min_element(ms.begin(), ms.end()),
            *std::max_element(ms.begin(), ms.end()));
    };
    editsAlone("item edit ", [&](int i) {
        doc->editItem<whitted::Sphere>(i, "radius", [](whitted::Sphere& s) { s.radius = 0.2; });
    });
    editsAlone("scene edit", [&](int i) {
        doc->edit("radius", [i](Scene& s) { s.spheres[200 + i].radius = 0.2; });
    });
    std::printf("peak memory: %.0f MB before the edits, %.0f MB after 400 (undo keeps deltas)\n",
                rssBefore / 1024.0, maxRssKb() / 1024.0);
    return 0;
}
