#include "ray_tree_dock/ray_tree_worker.h"

#include <exception>
#include <utility>

#include "base/thread_priority.h"
#include "document/scene_document.h"

namespace whitted::ui {

namespace {

void nameHits(const Scene& scene, const RayTreeNode& node, QHash<int, QString>& names) {
    if (node.hit >= 0 && node.kind != RayTreeNode::Kind::Shadow && !names.contains(node.hit))
        names.insert(node.hit, itemName(scene, ItemKind::Sphere, node.hit));
    for (const RayTreeNode& child : node.children) nameHits(scene, child, names);
}

void describeScene(const Scene& scene, RayTreeResult& result) {
    result.precision = scene.render.precision;
    result.width = scene.render.width;
    result.height = scene.render.height;
    result.maxDepth = scene.render.maxDepth;
    nameHits(scene, result.inFloat.root, result.sphereNames);
    nameHits(scene, result.inDouble.root, result.sphereNames);
    for (std::size_t i = 0; i < scene.lights.size(); ++i)
        result.lightNames.append(itemName(scene, ItemKind::Light, int(i)));
}

}  // namespace

// A side view: the main render and the GUI should win.
RayTreeWorker::RayTreeWorker(QObject* parent)
    : QObject(parent),
      requests_(
          RequestThread<Request>::Policy::LatestWins,
          [this](Request&& request, quint64 generation) { trace(std::move(request), generation); },
          lowerThisThreadsPriority) {}

quint64 RayTreeWorker::request(std::shared_ptr<const Scene> scene, QPoint pixel) {
    return requests_.request({std::move(scene), pixel});
}

void RayTreeWorker::trace(Request&& request, quint64 generation) {
    RayTreeResult result;
    result.generation = generation;
    result.pixel = request.pixel;
    try {
        const Scene& scene = *request.scene;
        result.inFloat =
            pixelRayTree(scene, request.pixel.x(), request.pixel.y(), Precision::Float);
        if (requests_.stale(generation)) return;
        result.inDouble =
            pixelRayTree(scene, request.pixel.x(), request.pixel.y(), Precision::Double);
    } catch (const std::exception& e) {
        result.error = QString::fromStdString(e.what());
    }
    if (requests_.stale(generation)) return;
    describeScene(*request.scene, result);
    request.scene.reset();
    {
        std::lock_guard lock(readyMutex_);
        ready_ = std::move(result);
    }
    emit treeReady();
}

std::optional<RayTreeResult> RayTreeWorker::takeTree() {
    std::lock_guard lock(readyMutex_);
    return std::exchange(ready_, std::nullopt);
}

}  // namespace whitted::ui
