// The editor's main window under test: a window on a 160x120 copy of the seed
// scene, the frames it shows, and the helpers that compare what the user sees
// (pixels, where a scene point lands) with the core's own answers. Shared by the
// GUI test files that drive the whole window: EditorWindowTest holds what all
// their fixtures have in common, MainWindowTest is the window on the seed with
// its first render shown.
#pragma once

#include <QApplication>
#include <QDir>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>
#include <QWindow>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "camera/view_projection.h"
#include "document/scene_document.h"
#include "editor/main_window.h"
#include "scene/scene_io.h"
#include "support/core_support.h"
#include "support/test_support.h"
#include "tracer/renderer.h"
#include "viewport/image_convert.h"
#include "viewport/render_view.h"

namespace whitted::ui {

namespace fs = std::filesystem;

constexpr double kPi = 3.14159265358979323846;
constexpr int kWidth = 160, kHeight = 120;
constexpr int kRenderTimeoutMs =
    20000;  // a 160x120 render takes milliseconds; CI machines are shared
enum SeedSphere { kBlueBall = 0, kPurpleBall = 1, kWhiteBall = 2, kFloor = 3 };

// Where scene point `p` appears in the image, in continuous pixel coordinates of
// the render size (x right, y down; pixel (i, j) covers [i, i+1) x [j, j+1)).
inline QPointF project(const Scene& scene, const Vec3& p) {
    const auto image = projectToImage(scene.camera, scene.render.width, scene.render.height, p);
    return image ? QPointF(image->x, image->y) : QPointF(-1, -1);
}

inline QPoint pixelOf(const Scene& scene, const Vec3& p) {
    const QPointF f = project(scene, p);
    return {int(std::floor(f.x())), int(std::floor(f.y()))};
}

// A colour channel that clearly dominates the other two.
inline bool blueDominant(QColor c) {
    return c.blue() > 2 * c.red() + 10 && c.blue() > 2 * c.green() + 10;
}
inline bool redDominant(QColor c) {
    return c.red() > 2 * c.blue() + 10 && c.red() > 2 * c.green() + 10;
}

// Exact image equality; on failure writes actual, expected and a diff image.
inline ::testing::AssertionResult sameImage(const QImage& actual, const QImage& expected) {
    const QImage a = actual.convertToFormat(QImage::Format_RGB32);
    const QImage e = expected.convertToFormat(QImage::Format_RGB32);
    if (a.size() != e.size())
        return ::testing::AssertionFailure() << "size " << a.width() << "x" << a.height()
                                             << ", expected " << e.width() << "x" << e.height();
    int differing = 0, firstX = -1, firstY = -1;
    QImage diff(a.size(), QImage::Format_RGB32);
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y), q = e.pixel(x, y);
            const bool same = p == q;
            diff.setPixel(x, y, same ? qRgb(0, 0, 0) : qRgb(255, 255, 255));
            if (!same && differing++ == 0) firstX = x, firstY = y;
        }
    if (differing == 0) return ::testing::AssertionSuccess();
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const QString stem = QDir(QDir::tempPath())
                             .filePath(QStringLiteral("whitted-%1-%2")
                                           .arg(info ? info->name() : "image")
                                           .arg(QCoreApplication::applicationPid()));
    a.save(stem + "-actual.png");
    e.save(stem + "-expected.png");
    diff.save(stem + "-diff.png");
    return ::testing::AssertionFailure()
           << differing << " of " << a.width() * a.height() << " pixels differ, first at ("
           << firstX << ", " << firstY << "): " << std::hex << a.pixel(firstX, firstY) << " vs "
           << e.pixel(firstX, firstY) << std::dec << "; images written to " << stem.toStdString()
           << "-{actual,expected,diff}.png";
}

// For "the image changed": equality without sameImage's diff files.
inline bool identical(const QImage& a, const QImage& b) {
    return a.convertToFormat(QImage::Format_RGB32) == b.convertToFormat(QImage::Format_RGB32);
}

// The core's own render of a scene, as the view shows it (8-bit sRGB).
inline QImage coreRender(const Scene& scene) {
    return toQImage(render(scene).image);
}

// Everything that reached the view (MainWindow::frameShown).
class FrameLog {
  public:
    explicit FrameLog(MainWindow& window) {
        connection_ = QObject::connect(&window, &MainWindow::frameShown, &window,
                                       [this](const RenderFrame& f) {
                                           generations.push_back(f.generation);
                                           lastCovers = f.image.size() * f.block;
                                           if (!f.renderComplete) return;
                                           ++completed;
                                           lastComplete = f;
                                       });
    }
    ~FrameLog() { QObject::disconnect(connection_); }
    FrameLog(const FrameLog&) = delete;
    FrameLog& operator=(const FrameLog&) = delete;

    int completed = 0;                 // frames shown with renderComplete
    RenderFrame lastComplete;          // the last of them
    std::vector<quint64> generations;  // of every frame shown, in order
    QSize
        lastCovers;  // render pixels the last frame covers (a preview: its pixels times its block)

  private:
    QMetaObject::Connection connection_;
};

// What the fixtures of the whole window share: a temporary directory for the
// scene file, the window, its document, the frames it shows and the waits for
// them. A subclass shows the window (showWindow) and opens its scene in SetUp.
class EditorWindowTest : public ::testing::Test {
  protected:
    void TearDown() override {
        log.reset();
        window.reset();
    }

    // The seed at width x height saved as seed.json in `dir`; sets scenePath.
    void writeSeedFile(int width = kWidth, int height = kHeight) {
        scenePath = QString::fromStdString(test::saveSceneIn(dir, test::seedScene(width, height)));
    }

    // A new MainWindow of that size, shown and exposed, its frames logged from now on.
    ::testing::AssertionResult showWindow(QSize size) {
        window = std::make_unique<MainWindow>();
        window->resize(size);
        window->show();
        if (!QTest::qWaitForWindowExposed(window.get()))
            return ::testing::AssertionFailure() << "the window was never exposed";
        log = std::make_unique<FrameLog>(*window);
        doc = window->document();
        return ::testing::AssertionSuccess();
    }

    ::testing::AssertionResult openFile(const QString& path) {
        if (window->openFile(path)) return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << window->lastError().toStdString();
    }

    // Opens the file and waits for the complete frame of its render.
    ::testing::AssertionResult openAndWait(const QString& path) {
        const int before = log->completed;
        if (auto opened = openFile(path); !opened) return opened;
        return waitForRender(before);
    }

    // Waits until a complete frame is shown after `completedBefore` were.
    ::testing::AssertionResult waitForRender(int completedBefore) {
        if (QTest::qWaitFor([&] { return log->completed > completedBefore; }, renderTimeoutMs))
            return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure()
               << "no complete frame within " << renderTimeoutMs << " ms";
    }

    // One document edit, then the complete frame of its render.
    ::testing::AssertionResult editAndWait(const std::function<void(Scene&)>& change) {
        const int before = log->completed;
        QString error;
        if (!doc->edit(QStringLiteral("test edit"), change, &error))
            return ::testing::AssertionFailure() << "edit refused: " << error.toStdString();
        return waitForRender(before);
    }

    // The window's child of that object name; a failure when there is none.
    template <class W>
    W* child(const char* name) const {
        W* w = window->findChild<W*>(QString::fromLatin1(name));
        EXPECT_NE(w, nullptr) << name;
        return w;
    }

    int renderTimeoutMs = kRenderTimeoutMs;
    test::TempDir dir;
    QString scenePath;
    std::unique_ptr<MainWindow> window;
    std::unique_ptr<FrameLog> log;
    SceneDocument* doc = nullptr;
};

// A window on a 160x120 copy of the seed scene, saved (clean) in a temporary
// directory, its first render shown.
class MainWindowTest : public EditorWindowTest {
  protected:
    void SetUp() override {
        writeSeedFile();
        ASSERT_TRUE(showWindow({1200, 800}));
        view = window->renderView();
        ASSERT_TRUE(openAndWait(scenePath));
        ASSERT_EQ(view->frame().size(), QSize(kWidth, kHeight));
    }

    void TearDown() override {
        // Frames reach the view newest generation last: a stale frame never follows a newer one.
        if (log) {
            EXPECT_TRUE(std::is_sorted(log->generations.begin(), log->generations.end()))
                << "a frame of an older generation was shown after a newer one";
        }
        EditorWindowTest::TearDown();
    }

    // Undo or redo, then the complete frame.
    ::testing::AssertionResult undoAndWait(bool redo = false) {
        const int before = log->completed;
        redo ? doc->undoStack()->redo() : doc->undoStack()->undo();
        return waitForRender(before);
    }

    // The widget point over continuous image point `p` (pixels of the render size).
    QPoint widgetPoint(QPointF p) const {
        const QRect r = view->imageRect();
        return r.topLeft() +
               QPoint(int(p.x() * r.width() / kWidth), int(p.y() * r.height() / kHeight));
    }

    QString shownTitle() const { return window->windowHandle()->title(); }

    RenderView* view = nullptr;
};

}  // namespace whitted::ui
