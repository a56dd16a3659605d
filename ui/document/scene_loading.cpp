#include "document/scene_loading.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QFileInfo>
#include <QProgressDialog>

#include <chrono>
#include <future>
#include <thread>

#include "scene/scene_io.h"

namespace whitted::ui {

namespace {

// QProgressDialog's own default, and about when a wait starts to feel like one.
constexpr int kShowDialogAfterMs = 300;
constexpr int kDialogSteps = 1000;
// Files read within this (about 3 MB, 20,000 spheres) are read with the GUI
// thread waiting, too short to notice.
constexpr std::chrono::milliseconds kEventLoopAfter{100};

}  // namespace

std::optional<Scene> loadSceneShowingProgress(QWidget* parent, const QString& path, QString* error,
                                              const LoadProgressShown& onProgress) {
    QProgressDialog dialog(
        QCoreApplication::translate("SceneLoading", "Opening %1…").arg(QFileInfo(path).fileName()),
        QString(), 0, kDialogSteps, parent);
    dialog.setWindowTitle(QCoreApplication::translate("SceneLoading", "Open Scene"));
    dialog.setObjectName(QStringLiteral("openProgress"));
    dialog.setWindowModality(Qt::WindowModal);
    dialog.setMinimumDuration(kShowDialogAfterMs);
    dialog.setCancelButton(nullptr);  // core's reading cannot be interrupted

    // Everything the worker sends is queued to `loop`, in order, so the last
    // progress report arrives before the quit; events still queued when `loop`
    // goes away are dropped with it.
    QEventLoop loop;
    std::promise<void> finished;
    std::future<void> finishedSoon = finished.get_future();
    std::optional<Scene> scene;
    QString message;
    std::thread worker([&] {
        const auto report = [&](std::uintmax_t done, std::uintmax_t total) {
            QMetaObject::invokeMethod(
                &loop,
                [&dialog, &onProgress, done = qint64(done), total = qint64(total)] {
                    // Reported first: a shown modal dialog's setValue() processes
                    // events, the later reports among them.
                    if (onProgress) onProgress(done, total);
                    dialog.setValue(total > 0 ? int(done * kDialogSteps / total) : 0);
                },
                Qt::QueuedConnection);
        };
        try {
            scene = loadScene(path.toStdString(), report);
        } catch (const std::exception& e) {
            message = QString::fromStdString(e.what());
        }
        QMetaObject::invokeMethod(&loop, &QEventLoop::quit, Qt::QueuedConnection);
        finished.set_value();
    });
    // A small file is read before the event loop would have turned: the
    // caller then sees no events at all during the open, as before files were
    // read on a thread (a frame of the old scene arriving mid-open, say).
    if (finishedSoon.wait_for(kEventLoopAfter) != std::future_status::ready) loop.exec();
    worker.join();
    if (!scene && error) *error = message;
    return scene;
}

}  // namespace whitted::ui
