// The Ray Tree dock's thread: traces one pixel's ray tree in float and in
// double (core's pixelRayTree) away from the GUI thread, the newest request
// winning (core/base/request_thread.h). A large scene's trees take its
// preparation, a tree built, twice: a million spheres take a second.
#pragma once

#include <memory>
#include <mutex>
#include <optional>

#include <QHash>
#include <QObject>
#include <QPoint>
#include <QString>
#include <QStringList>

#include "analysis/pixel_ray_tree.h"
#include "base/request_thread.h"
#include "scene/scene.h"

namespace whitted::ui {

struct RayTreeResult {
    quint64 generation = 0;
    QPoint pixel;
    // Of the scene traced: its precision, picture size and maximum depth.
    Precision precision = Precision::Float;
    int width = 0, height = 0, maxDepth = 0;
    // The names of the spheres the trees hit and of the lights: the result
    // keeps no snapshot of the scene, which would make the next edit copy it.
    QHash<int, QString> sphereNames;
    QStringList lightNames;
    PixelRayTree inFloat, inDouble;
    QString error;  // set when the scene could not be traced; the trees are then empty
};

class RayTreeWorker : public QObject {
    Q_OBJECT
  public:
    explicit RayTreeWorker(QObject* parent = nullptr);
    ~RayTreeWorker() override = default;  // joins the thread once the running trace ends

    // Traces `pixel` of `scene` in both precisions; returns the request's generation.
    quint64 request(std::shared_ptr<const Scene> scene, QPoint pixel);
    quint64 latestGeneration() const { return requests_.latestTicket(); }

    // In the GUI thread, after treeReady: the newest tree traced, once.
    std::optional<RayTreeResult> takeTree();

  signals:
    // From the worker's thread: a tree waits in takeTree(). The tree itself
    // passes under our own mutex, not inside Qt's queued signal, so that
    // ThreadSanitizer sees the hand-over (as RenderWorker's frames do).
    void treeReady();

  private:
    struct Request {
        std::shared_ptr<const Scene> scene;
        QPoint pixel;
    };
    void trace(Request&& request, quint64 generation);

    std::mutex readyMutex_;
    std::optional<RayTreeResult> ready_;  // guarded by readyMutex_
    // Last, so that it stops and joins its thread before the rest goes.
    RequestThread<Request> requests_;
};

}  // namespace whitted::ui
