#include "scene_document.h"

#include <QUndoCommand>

#include "scene_io.h"

namespace whitted::ui {

namespace {

// True when two scenes list the same items under the same names, in order.
bool sameStructure(const Scene& a, const Scene& b) {
    auto names = [](const auto& list) {
        std::vector<std::string> out;
        for (const auto& item : list) out.push_back(item.name);
        return out;
    };
    return names(a.spheres) == names(b.spheres) && names(a.lights) == names(b.lights) &&
           names(a.materials) == names(b.materials);
}

}  // namespace

// The whole scene before and after: scenes are plain values, and a copy is
// simpler and safer than an inverse for every kind of edit.
class SceneEditCommand : public QUndoCommand {
  public:
    SceneEditCommand(SceneDocument* doc, Scene before, Scene after, const QString& text)
        : QUndoCommand(text), doc_(doc), before_(std::move(before)), after_(std::move(after)) {}
    void undo() override { doc_->apply(before_); }
    void redo() override { doc_->apply(after_); }

  private:
    SceneDocument* doc_;
    Scene before_, after_;
};

SceneDocument::SceneDocument(QObject* parent) : QObject(parent) {
    connect(&undo_, &QUndoStack::cleanChanged, this,
            [this](bool clean) { emit modifiedChanged(!clean); });
}

void SceneDocument::apply(const Scene& scene) {
    const bool structural = !sameStructure(scene_, scene);
    scene_ = scene;
    if (structural) emit structureChanged();
    emit sceneChanged();
}

void SceneDocument::reset(const Scene& scene, const QString& filePath) {
    undo_.clear();
    gestureDepth_ = 0;
    scene_ = scene;
    filePath_ = filePath;
    emit filePathChanged(filePath_);
    emit structureChanged();
    emit sceneChanged();
    emit modifiedChanged(false);
}

bool SceneDocument::load(const QString& path, QString* error) {
    try {
        reset(loadScene(path.toStdString()), path);
        return true;
    } catch (const std::exception& e) {
        if (error) *error = QString::fromStdString(e.what());
        return false;
    }
}

bool SceneDocument::save(const QString& path, QString* error) {
    try {
        saveScene(scene_, path.toStdString());
    } catch (const std::exception& e) {
        if (error) *error = QString::fromStdString(e.what());
        return false;
    }
    undo_.setClean();
    if (filePath_ != path) {
        filePath_ = path;
        emit filePathChanged(filePath_);
    }
    return true;
}

bool SceneDocument::edit(const QString& text, const std::function<void(Scene&)>& change,
                         QString* error) {
    Scene after = scene_;
    change(after);
    if (after == scene_) return true;
    if (auto problem = validateScene(after)) {
        if (error) *error = QString::fromStdString(problem->jsonPath + ": " + problem->reason);
        return false;
    }
    undo_.push(new SceneEditCommand(this, scene_, std::move(after), text));
    return true;
}

void SceneDocument::beginGesture(const QString& text) {
    if (gestureDepth_++ == 0) undo_.beginMacro(text);
}

void SceneDocument::endGesture() {
    if (gestureDepth_ == 0) return;
    if (--gestureDepth_ == 0) undo_.endMacro();
}

QString SceneDocument::uniqueName(ItemKind kind, const QString& stem) const {
    for (int n = itemCount(scene_, kind) + 1;; ++n) {
        const QString candidate = QStringLiteral("%1 %2").arg(stem).arg(n);
        bool taken = false;
        for (int i = 0; i < itemCount(scene_, kind) && !taken; ++i)
            taken = itemName(scene_, kind, i) == candidate;
        if (!taken) return candidate;
    }
}

int itemCount(const Scene& scene, ItemKind kind) {
    switch (kind) {
        case ItemKind::Sphere:
            return static_cast<int>(scene.spheres.size());
        case ItemKind::Light:
            return static_cast<int>(scene.lights.size());
        case ItemKind::Material:
            return static_cast<int>(scene.materials.size());
    }
    return 0;
}

QString itemName(const Scene& scene, ItemKind kind, int index) {
    if (index < 0 || index >= itemCount(scene, kind)) return {};
    switch (kind) {
        case ItemKind::Sphere:
            return QString::fromStdString(scene.spheres[index].name);
        case ItemKind::Light:
            return QString::fromStdString(scene.lights[index].name);
        case ItemKind::Material:
            return QString::fromStdString(scene.materials[index].name);
    }
    return {};
}

}  // namespace whitted::ui
