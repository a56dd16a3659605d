// Building a scene with the mouse, timed in a real MainWindow (offscreen): the
// events go to the shown window as a user's do, and each figure runs from the
// event to the first preview frame of the changed scene reaching the window.
//   (a) G, then mouse moves: each move's first preview, on the seed and on a
//       field of 100,000 balls (the sphere tree refits for a move);
//   (b) on a field of 1,000,000 balls: B and a drag round a tenth of them, the
//       selection's time; one material given to all of them through the
//       sphere page, to its first preview; and its undo, to its first preview
//       (each seven times: medians and the worst); then G and seven pointer
//       moves of all of them, each to its first preview.
// Targets: 30 ms a move, 150 ms the material and its undo. Prints its figures;
// not a test.
//   build/bin/bench_editor_gestures [MOVES] [BIG_FIELD]   (default 30 1000000)
#include <QApplication>
#include <QComboBox>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTest>
#include <QTimer>
#include <QUndoStack>
#include <QWindow>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "base/heap_reuse.h"
#include "big_scene.h"
#include "camera/view_projection.h"
#include "editor/main_window.h"
#include "panels/scene_panel.h"
#include "viewport/render_view.h"

namespace {

using whitted::Scene;
using whitted::ui::MainWindow;
using whitted::ui::RenderFrame;

constexpr double kMoveTargetMs = 30.0;
constexpr double kMaterialTargetMs = 150.0;
constexpr int kRepeats = 7;  // of the material and its undo, each a whole render apart

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// Waits in the event loop for the window's first preview of a render asked for
// after `since` started; its milliseconds since then, or -1 after 10 s. With
// `rendering`, also the milliseconds the worker spent on it (RenderFrame::seconds).
double firstPreviewMs(MainWindow& window, const QElapsedTimer& since, double* rendering = nullptr) {
    double ms = -1;
    // An event loop of its own, left when the frame comes: QTest::qWaitFor
    // sleeps 10 ms between its looks, which the figures would include.
    QEventLoop loop;
    const auto connection =
        QObject::connect(&window, &MainWindow::frameShown, [&](const RenderFrame& f) {
            if (ms >= 0 || f.generation != window.renderWorker().latestGeneration()) return;
            ms = double(since.nsecsElapsed()) / 1e6;
            if (rendering) *rendering = f.seconds * 1e3;
            loop.quit();
        });
    QTimer::singleShot(10000, &loop, &QEventLoop::quit);
    if (ms < 0) loop.exec();
    if (ms < 0) {  // figures without the frame would measure nothing
        std::fprintf(stderr, "bench_editor_gestures: no preview in 10 s\n");
        std::exit(1);
    }
    QObject::disconnect(connection);
    return ms;
}

struct Window {
    explicit Window(const Scene& scene) {
        window.show();
        if (!QTest::qWaitForWindowExposed(&window)) {
            std::fprintf(stderr, "bench_editor_gestures: window not shown\n");
            std::exit(1);
        }
        window.document()->reset(scene, QString());
        QTest::qWait(300);  // the first render and the tree built
    }
    QPoint inWindow(QPointF viewPoint) {
        return window.renderView()->mapTo(&window, viewPoint.toPoint());
    }
    QPointF drawn(const whitted::Vec3& p) {
        const Scene& s = window.document()->scene();
        const QRect r = window.renderView()->imageRect();
        const auto image = whitted::projectToImage(s.camera, s.render.width, s.render.height, p);
        return {r.left() + image->x * r.width() / s.render.width,
                r.top() + image->y * r.height() / s.render.height};
    }
    MainWindow window;
};

// A ball near the middle of the picture, to be grabbed.
int ballInTheMiddle(const Scene& s) {
    for (int i = 0; i < int(s.spheres.size()); ++i) {
        const auto p =
            whitted::projectToImage(s.camera, s.render.width, s.render.height, s.spheres[i].center);
        if (p && std::abs(p->x / s.render.width - 0.5) < 0.15 &&
            std::abs(p->y / s.render.height - 0.5) < 0.15 && s.spheres[i].radius < 1000)
            return i;
    }
    return 0;
}

// G with the pointer at `at` (in the window) and the selection as it is, then
// `moves` pointer moves of 3 pixels: each one's first preview, the window's
// handling of each and the worker's render of it; then Escape.
std::vector<double> dragWithG(MainWindow& window, QPoint at, int moves,
                              std::vector<double>& handled, std::vector<double>& rendered) {
    QWindow* shown = window.windowHandle();
    QTest::mouseMove(shown, at);
    QTest::keyClick(shown, Qt::Key_G);
    std::vector<double> ms;
    for (int i = 0; i < moves; ++i) {
        at += QPoint(i % 2 ? -3 : 3, 1);
        QElapsedTimer t;
        t.start();
        QTest::mouseMove(shown, at);
        handled.push_back(double(t.nsecsElapsed()) / 1e6);
        double rendering = 0;
        ms.push_back(firstPreviewMs(window, t, &rendering));
        rendered.push_back(rendering);
    }
    QTest::keyClick(shown, Qt::Key_Escape);
    return ms;
}

// G on sphere `index`, then `moves` pointer moves of 3 pixels: each one's first preview.
std::vector<double> moveTimes(const Scene& scene, int index, int moves,
                              std::vector<double>& handled, std::vector<double>& rendered) {
    Window w(scene);
    w.window.scenePanel()->select(whitted::ui::ItemKind::Sphere, index);
    const QPoint at = w.inWindow(w.drawn(scene.spheres[index].center));
    return dragWithG(w.window, at, moves, handled, rendered);
}

// The widget-space box, from the left of the picture, holding the centres of a
// tenth of the balls (or of all it can show).
QRect tenthBox(Window& w, const Scene& scene) {
    const QRect r = w.window.renderView()->imageRect();
    std::vector<double> xs;
    for (const auto& sp : scene.spheres)
        if (whitted::projectToImage(scene.camera, scene.render.width, scene.render.height,
                                    sp.center))
            if (const QPointF at = w.drawn(sp.center); r.contains(at.toPoint()))
                xs.push_back(at.x());
    std::sort(xs.begin(), xs.end());
    const int right = int(xs[std::min(xs.size() - 1, scene.spheres.size() / 10)]);
    return QRect(QPoint(r.left(), r.top()), QPoint(right, r.bottom()));
}

void bigField(int count) {
    const Scene scene = whitted::bench::bigScene(count);
    Window w(scene);
    QWindow* shown = w.window.windowHandle();
    const QRect box = tenthBox(w, scene);
    QElapsedTimer t;
    t.start();
    QTest::keyClick(shown, Qt::Key_B);
    QTest::mousePress(shown, Qt::LeftButton, {}, w.inWindow(box.topLeft()));
    QTest::mouseMove(shown, w.inWindow(box.center()));
    QTest::mouseMove(shown, w.inWindow(box.bottomRight()));
    QTest::mouseRelease(shown, Qt::LeftButton, {}, w.inWindow(box.bottomRight()));
    QApplication::processEvents();
    const double selectMs = double(t.nsecsElapsed()) / 1e6;
    const int selected = w.window.document()->selection()->count();

    // The material and its undo, kRepeats times each: the medians, and the worst.
    auto* material = w.window.findChild<QComboBox*>(QStringLiteral("sphereMaterial"));
    const int white = material->findText(QStringLiteral("white"));
    std::vector<double> materialMs, materialHandledMs, undoMs, undoHandledMs;
    for (int k = 0; k < kRepeats; ++k) {
        QTest::qWait(300);
        t.start();
        material->setCurrentIndex(white == material->currentIndex() ? 0 : white);
        materialHandledMs.push_back(double(t.nsecsElapsed()) / 1e6);
        materialMs.push_back(firstPreviewMs(w.window, t));
        QTest::qWait(300);
        t.start();
        w.window.document()->undoStack()->undo();
        undoHandledMs.push_back(double(t.nsecsElapsed()) / 1e6);
        undoMs.push_back(firstPreviewMs(w.window, t));
    }
    // For comparison: any edit of so large a scene, one sphere's radius.
    QTest::qWait(300);
    t.start();
    w.window.document()->editItem<whitted::Sphere>(w.window.document()->selection()->active(),
                                                   QStringLiteral("Change radius"),
                                                   [](whitted::Sphere& sp) { sp.radius *= 1.01; });
    const double oneHandledMs = double(t.nsecsElapsed()) / 1e6;
    const double oneMs = firstPreviewMs(w.window, t);
    // G with all of them selected, each pointer move to its first preview.
    QTest::qWait(300);
    std::vector<double> moveHandledMs, moveRenderedMs;
    const std::vector<double> moveMs =
        dragWithG(w.window, w.inWindow(box.center()), kRepeats, moveHandledMs, moveRenderedMs);
    std::printf("%d balls: B and a drag selected %d (%.0f %%) in %.0f ms\n", count, selected,
                100.0 * selected / count, selectMs);
    auto report = [](const char* what, const std::vector<double>& ms,
                     const std::vector<double>& handled) {
        std::printf("  %-34s median %6.1f ms (max %6.1f)  target %3.0f ms: %.2fx\n", what,
                    median(ms), *std::max_element(ms.begin(), ms.end()), kMaterialTargetMs,
                    median(ms) / kMaterialTargetMs);
        std::printf("  %-34s of which the window's handling: median %.1f ms\n", "",
                    median(handled));
    };
    report("one material for all of them:", materialMs, materialHandledMs);
    report("its undo:", undoMs, undoHandledMs);
    std::printf(
        "  %-34s median %6.1f ms (max %6.1f); the window's handling: median %.1f ms, the "
        "worker's render: median %.1f ms\n",
        "G, a pointer move of all of them:", median(moveMs),
        *std::max_element(moveMs.begin(), moveMs.end()), median(moveHandledMs),
        median(moveRenderedMs));
    std::printf(
        "  for comparison, one sphere's radius: %.1f ms to its first preview (%.1f ms "
        "handling)\n",
        oneMs, oneHandledMs);
}

void reportMoves(const char* what, const Scene& scene, int moves) {
    std::vector<double> handled, rendered;
    const std::vector<double> ms =
        moveTimes(scene, ballInTheMiddle(scene), moves, handled, rendered);
    const auto [low, high] = std::minmax_element(ms.begin(), ms.end());
    std::printf("%-16s median %6.1f ms (min %6.1f, max %6.1f)  target %2.0f ms: %.2fx\n", what,
                median(ms), *low, *high, kMoveTargetMs, median(ms) / kMoveTargetMs);
    std::printf(
        "%-16s of which the window's handling of the event: median %.1f ms, the "
        "worker's render: median %.1f ms\n",
        "", median(handled), median(rendered));
}

}  // namespace

int main(int argc, char** argv) {
    whitted::reuseHeapForLargeBlocks();  // as the editor's main() does
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    const int moves = argc > 1 ? std::max(1, std::atoi(argv[1])) : 30;
    const int big = argc > 2 ? std::max(10, std::atoi(argv[2])) : 1000000;
    std::printf("G and %d pointer moves of 3 pixels, each to its first preview frame:\n", moves);
    const Scene seed = whitted::loadScene(WHITTED_SCENES_DIR "/seed.json");
    reportMoves("seed scene:", seed, moves);
    reportMoves("100,000 balls:", whitted::bench::bigScene(100000), moves);
    const std::string bigLabel = std::to_string(big) + " balls:";
    reportMoves(bigLabel.c_str(), whitted::bench::bigScene(big), moves);
    bigField(big);
    std::printf("(ratio = figure / target; at most 1.00 meets the target)\n");
    return 0;
}
