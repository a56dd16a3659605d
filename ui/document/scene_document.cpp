#include "document/scene_document.h"

#include <optional>
#include <type_traits>
#include <utility>

#include <QElapsedTimer>
#include <QUndoCommand>

#include "document/edit_messages.h"
#include "scene/scene_io.h"

namespace whitted::ui {

// What one edit changed, and only that: the small top-level values whole, and
// of each list either the items that changed (when its length stayed) or the
// whole list. Whole scenes before and after were simpler, but a scene of
// 100,000 spheres is 15 MB, and every edit kept two of them for undo.
template <class T>
class ListDelta {
  public:
    ListDelta() = default;  // nothing changed
    // Item `index` alone changed, from `before` to `after` (an item edit).
    ListDelta(std::size_t index, T before, T after)
        : index_{index}, before_{std::move(before)}, after_{std::move(after)} {}
    // Items `index` (ascending) changed from `before` to `after` (an items edit).
    ListDelta(std::vector<std::size_t> index, std::vector<T> before, std::vector<T> after)
        : index_{std::move(index)}, before_{std::move(before)}, after_{std::move(after)} {}
    ListDelta(const std::vector<T>& before, const std::vector<T>& after) {
        if (before.size() != after.size()) {
            whole_ = true;
            before_ = before;
            after_ = after;
            return;
        }
        for (std::size_t i = 0; i < before.size(); ++i)
            if (!(before[i] == after[i])) {
                index_.push_back(i);
                before_.push_back(before[i]);
                after_.push_back(after[i]);
            }
    }
    bool empty() const { return !whole_ && index_.empty(); }
    // Items edits of the same items, which `next` continues: this one then
    // ends where `next` does (a gesture's steps are kept as one).
    bool continuesWith(const ListDelta& next) const {
        return !whole_ && !next.whole_ && index_ == next.index_;
    }
    void takeAfter(const ListDelta& next) { after_ = next.after_; }
    // Whether applying the change to `list` adds, removes, renames or
    // reorders items.
    bool changesStructure(const std::vector<T>& list, bool forward) const {
        if (whole_) return true;
        const std::vector<T>& to = forward ? after_ : before_;
        for (std::size_t k = 0; k < index_.size(); ++k)
            if (list[index_[k]].name != to[k].name) return true;
        return false;
    }
    // Whether applying the change to `list` moves, resizes, adds or removes a
    // sphere: what the view's marks of a selection follow.
    bool changesGeometry(const std::vector<T>& list, bool forward) const {
        if constexpr (!std::is_same_v<T, Sphere>) {
            return false;
        } else {
            if (whole_) return true;
            const std::vector<T>& to = forward ? after_ : before_;
            for (std::size_t k = 0; k < index_.size(); ++k)
                if (list[index_[k]].center != to[k].center ||
                    list[index_[k]].radius != to[k].radius)
                    return true;
            return false;
        }
    }
    // Applies the change forwards (redo) or backwards (undo); true when it
    // added, removed, renamed or reordered items.
    bool apply(std::vector<T>& list, bool forward) const {
        const std::vector<T>& to = forward ? after_ : before_;
        if (whole_) {
            list = to;
            return true;
        }
        bool renamed = false;
        for (std::size_t k = 0; k < index_.size(); ++k) {
            renamed = renamed || list[index_[k]].name != to[k].name;
            list[index_[k]] = to[k];
        }
        return renamed;
    }

  private:
    bool whole_ = false;
    std::vector<std::size_t> index_;
    std::vector<T> before_, after_;
};

struct SceneDelta {
    SceneDelta(const Scene& before, const Scene& after)
        : spheres(before.spheres, after.spheres),
          lights(before.lights, after.lights),
          materials(before.materials, after.materials) {
        headBefore = head(before);
        headAfter = head(after);
    }
    // An item edit of `scene`: one item of one list, the rest as it is.
    template <class T>
    static SceneDelta item(const Scene& scene, std::size_t index, T before, T after) {
        return items(scene, ListDelta<T>(index, std::move(before), std::move(after)));
    }
    template <class T>
    static SceneDelta items(const Scene& scene, ListDelta<T> change) {
        SceneDelta delta(head(scene));
        if constexpr (std::is_same_v<T, Sphere>)
            delta.spheres = std::move(change);
        else if constexpr (std::is_same_v<T, Light>)
            delta.lights = std::move(change);
        else
            delta.materials = std::move(change);
        return delta;
    }
    // The scene without its lists.
    static Scene head(const Scene& s) {
        Scene h;
        h.camera = s.camera;
        h.render = s.render;
        h.background = s.background;
        h.ambient = s.ambient;
        return h;
    }
    // Only the camera, render settings, background or ambient changed.
    bool headOnly() const { return spheres.empty() && lights.empty() && materials.empty(); }
    // Changed items of one list alone, the rest as it was.
    bool itemsOnly() const {
        const int lists = !spheres.empty() + !lights.empty() + !materials.empty();
        return lists == 1 && headBefore == headAfter;
    }
    // Takes in `next`, an items edit of the same items that follows this one.
    bool absorb(const SceneDelta& next) {
        if (!itemsOnly() || !next.itemsOnly() || !(headAfter == next.headBefore) ||
            !spheres.continuesWith(next.spheres) || !lights.continuesWith(next.lights) ||
            !materials.continuesWith(next.materials))
            return false;
        spheres.takeAfter(next.spheres);
        lights.takeAfter(next.lights);
        materials.takeAfter(next.materials);
        return true;
    }
    Scene headBefore, headAfter;
    ListDelta<Sphere> spheres;
    ListDelta<Light> lights;
    ListDelta<Material> materials;

  private:
    explicit SceneDelta(const Scene& head) : headBefore(head), headAfter(head) {}
};

template <class T>
std::optional<SceneProblem> validateItemEdit(const Scene& scene, const T& edited,
                                             std::size_t index) {
    if constexpr (std::is_same_v<T, Sphere>)
        return validateSphereEdit(scene, edited, index);
    else if constexpr (std::is_same_v<T, Light>)
        return validateLightEdit(edited, index);
    else
        return validateMaterialEdit(edited, index);
}

class SceneEditCommand : public QUndoCommand {
  public:
    SceneEditCommand(SceneDocument* doc, SceneDelta delta, const QString& text, EditRun run)
        : QUndoCommand(text),
          doc_(doc),
          delta_(std::move(delta)),
          selectionBefore_(doc->selection_.snapshot()) {
        joinable_ = run == EditRun::Join && delta_.headOnly();
        sinceLast_.start();
    }
    // A move after an undo or redo starts a step of its own: they close the run.
    void undo() override {
        doc_->runOpen_ = false;
        doc_->applyDelta(delta_, false);
        doc_->selection_.restore(selectionBefore_);
    }
    void redo() override {
        if (pushed_) doc_->runOpen_ = false;
        pushed_ = true;  // the first redo is QUndoStack::push applying the edit
        doc_->applyDelta(delta_, true);
    }
    // QUndoStack asks the step on top whether a new one of the same id joins it.
    int id() const override { return joinable_ ? 1 : delta_.itemsOnly() ? 2 : -1; }
    bool mergeWith(const QUndoCommand* other) override {
        const auto* next = static_cast<const SceneEditCommand*>(other);
        // Inside a gesture (a drag of G, S or a slider), the edits of the same
        // items keep one before and one after: moving 100,000 spheres kept
        // 17 MB a pointer event.
        if (id() == 2) return doc_->gestureDepth_ > 0 && delta_.absorb(next->delta_);
        if (!doc_->runOpen_ || !joinable_ || !next->joinable_ ||
            sinceLast_.elapsed() >= SceneDocument::kRunGapMs)
            return false;
        delta_.headAfter = next->delta_.headAfter;
        if (text() != next->text()) setText(QObject::tr("Move camera"));
        sinceLast_.start();
        return true;
    }

  private:
    SceneDocument* doc_;
    SceneDelta delta_;
    SceneSelection::Snapshot selectionBefore_;  // the scene is as it was then after an undo
    bool joinable_ = false;
    bool pushed_ = false;
    QElapsedTimer sinceLast_;
};

Scene& SceneDocument::writableScene() {
    // Counted by taking one more reference: an atomic read-modify-write, which
    // orders what a holder read before it let go ahead of the writes that
    // follow (use_count() alone is a relaxed read, and ThreadSanitizer saw the
    // render thread's last reads race with them). Only this thread adds
    // holders (snapshot()), so a count it finds low stays low.
    const std::shared_ptr<Scene> counted = scene_;
    if (counted.use_count() > 2) scene_ = std::make_shared<Scene>(std::as_const(*scene_));
    return *scene_;
}

void SceneDocument::applyDelta(const SceneDelta& delta, bool forward) {
    emit aboutToWrite();
    Scene& scene = writableScene();
    const Scene& head = forward ? delta.headAfter : delta.headBefore;
    const bool settingsOnly = delta.headOnly() && head.camera == scene.camera &&
                              head.background == scene.background && head.ambient == scene.ambient;
    if (!settingsOnly) ++contentRevision_;
    scene.camera = head.camera;
    scene.render = head.render;
    scene.background = head.background;
    scene.ambient = head.ambient;
    const bool moves = [&] {
        switch (selection_.kind()) {
            case ItemKind::Sphere:
                return delta.spheres.changesStructure(scene.spheres, forward);
            case ItemKind::Light:
                return delta.lights.changesStructure(scene.lights, forward);
            case ItemKind::Material:
                return delta.materials.changesStructure(scene.materials, forward);
        }
        return false;
    }();
    if (moves) selection_.rememberNames(scene);
    if (delta.spheres.changesGeometry(scene.spheres, forward)) ++geometryRevision_;
    bool structural = delta.spheres.apply(scene.spheres, forward);
    structural = delta.lights.apply(scene.lights, forward) || structural;
    structural = delta.materials.apply(scene.materials, forward) || structural;
    if (moves) selection_.followNames(scene);
    if (structural) emit structureChanged();
    emit sceneChanged();
}

SceneDocument::SceneDocument(QObject* parent) : QObject(parent) {
    connect(&undo_, &QUndoStack::cleanChanged, this,
            [this](bool clean) { emit modifiedChanged(!clean); });
}

void SceneDocument::reset(Scene scene, const QString& filePath, bool validated) {
    undo_.clear();
    gestureDepth_ = 0;
    runOpen_ = false;
    scene_ = std::make_shared<Scene>(std::move(scene));
    ++contentRevision_;
    ++geometryRevision_;
    resetSceneValid_ = validated || !validateScene(*scene_);
    selection_.clear();
    filePath_ = filePath;
    emit filePathChanged(filePath_);
    emit structureChanged();
    emit sceneChanged();
    emit modifiedChanged(false);
}

bool SceneDocument::load(const QString& path, QString* error) {
    try {
        reset(loadScene(path.toStdString()), path, true);  // the loader validated it
        return true;
    } catch (const std::exception& e) {
        if (error) *error = QString::fromStdString(e.what());
        return false;
    }
}

bool SceneDocument::save(const QString& path, QString* error) {
    try {
        saveScene(*scene_, path.toStdString());
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
                         QString* error, EditRun run) {
    const Scene& before = *scene_;
    Scene after = before;
    change(after);
    if (after == before) return true;
    // Every state past the first is an edit that passed this check; the first
    // is whatever reset() was given.
    const bool valid = undo_.index() > 0 || resetSceneValid_;
    if (auto problem = valid ? validateEdit(before, after) : validateScene(after)) {
        if (error) *error = editProblemText(*problem, after);
        return false;
    }
    push(SceneDelta(before, after), text, run);
    return true;
}

void SceneDocument::push(SceneDelta delta, const QString& text, EditRun run) {
    undo_.push(new SceneEditCommand(this, std::move(delta), text, run));
    runOpen_ = run == EditRun::Join;
}

// A refused edit's words, which name the item's fields as the edit left them:
// worded in the scene with the edited item swapped in, and swapped back out
// before anyone can see it (the scene is written to: a copy, while a render
// still reads it).
template <class T>
QString refusalText(Scene& scene, const SceneProblem& problem, std::size_t index, T edited) {
    std::swap(itemsOf<T>(scene)[index], edited);
    const QString text = editProblemText(problem, scene);
    std::swap(itemsOf<T>(scene)[index], edited);
    return text;
}

template <class T>
bool SceneDocument::editItem(int index, const QString& text, const std::function<void(T&)>& change,
                             QString* error) {
    const std::vector<T>& items = itemsOf<T>(std::as_const(*scene_));
    if (index < 0 || index >= static_cast<int>(items.size())) return true;
    const auto i = static_cast<std::size_t>(index);
    T after = items[i];
    change(after);
    if (after == items[i]) return true;
    // A new name may clash with any other item's, or (a material's) leave
    // spheres without theirs; and a first state reset() was given invalid
    // needs the whole scene checked. Both are edit()'s, which does it all.
    if (after.name != items[i].name || !(undo_.index() > 0 || resetSceneValid_))
        return edit(
            text, [&](Scene& s) { itemsOf<T>(s)[i] = after; }, error);
    if (const auto problem = validateItemEdit<T>(*scene_, after, i)) {
        if (error) *error = refusalText<T>(writableScene(), *problem, i, after);
        return false;
    }
    push(SceneDelta::item(*scene_, i, items[i], std::move(after)), text, EditRun::Separate);
    return true;
}

template <class T>
bool SceneDocument::editItems(const std::vector<int>& indices, const QString& text,
                              const std::function<void(T&, int)>& change, QString* error) {
    const std::vector<T>& items = itemsOf<T>(std::as_const(*scene_));
    std::vector<std::size_t> changed;
    std::vector<T> before, after;
    changed.reserve(indices.size());
    before.reserve(indices.size());
    after.reserve(indices.size());
    for (int index : indices) {
        if (index < 0 || index >= static_cast<int>(items.size())) continue;
        const auto i = static_cast<std::size_t>(index);
        T item = items[i];
        change(item, index);
        if (item == items[i]) continue;
        changed.push_back(i);
        before.push_back(items[i]);
        after.push_back(std::move(item));
    }
    if (changed.empty()) return true;
    if (!(undo_.index() > 0 || resetSceneValid_))
        return edit(
            text,
            [&](Scene& s) {
                for (std::size_t k = 0; k < changed.size(); ++k)
                    itemsOf<T>(s)[changed[k]] = after[k];
            },
            error);
    // Each checked where it lies among the edited items: a selection of
    // 100,000 spheres swapped into the scene and back spent 20 to 50 ms a
    // pointer move of G reaching into the list of a million.
    for (std::size_t k = 0; k < changed.size(); ++k) {
        std::optional<SceneProblem> problem =
            after[k].name != before[k].name ? SceneProblem{"", "a name cannot change with others"}
                                            : validateItemEdit<T>(*scene_, after[k], changed[k]);
        if (!problem) continue;
        if (error) *error = refusalText<T>(writableScene(), *problem, changed[k], after[k]);
        return false;
    }
    push(SceneDelta::items(*scene_,
                           ListDelta<T>(std::move(changed), std::move(before), std::move(after))),
         text, EditRun::Separate);
    return true;
}

template bool SceneDocument::editItems<Sphere>(const std::vector<int>&, const QString&,
                                               const std::function<void(Sphere&, int)>&, QString*);
template bool SceneDocument::editItems<Light>(const std::vector<int>&, const QString&,
                                              const std::function<void(Light&, int)>&, QString*);
template bool SceneDocument::editItems<Material>(const std::vector<int>&, const QString&,
                                                 const std::function<void(Material&, int)>&,
                                                 QString*);

template bool SceneDocument::editItem<Sphere>(int, const QString&,
                                              const std::function<void(Sphere&)>&, QString*);
template bool SceneDocument::editItem<Light>(int, const QString&,
                                             const std::function<void(Light&)>&, QString*);
template bool SceneDocument::editItem<Material>(int, const QString&,
                                                const std::function<void(Material&)>&, QString*);

void SceneDocument::beginGesture(const QString& text) {
    if (gestureDepth_++ == 0) undo_.beginMacro(text);
}

void SceneDocument::endGesture() {
    if (gestureDepth_ == 0) return;
    if (--gestureDepth_ > 0) return;
    undo_.endMacro();
    emit gestureEnded();
}

void SceneDocument::discardGesture() {
    if (gestureDepth_ == 0) return;
    if (--gestureDepth_ > 0) return;
    undo_.endMacro();
    // An obsolete step is taken off the stack by undo() without being undone:
    // the scene is already as it was.
    auto* step = const_cast<QUndoCommand*>(undo_.command(undo_.index() - 1));
    step->setObsolete(true);
    undo_.undo();
    emit gestureEnded();
}

QString SceneDocument::uniqueName(ItemKind kind, const QString& stem) const {
    for (int n = itemCount(*scene_, kind) + 1;; ++n) {
        const QString candidate = QStringLiteral("%1 %2").arg(stem).arg(n);
        bool taken = false;
        for (int i = 0; i < itemCount(*scene_, kind) && !taken; ++i)
            taken = itemName(*scene_, kind, i) == candidate;
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
    return QString::fromStdString(itemNameOf(scene, kind, index));
}

QString kindNoun(ItemKind kind) {
    switch (kind) {
        case ItemKind::Sphere:
            return QObject::tr("sphere");
        case ItemKind::Light:
            return QObject::tr("light");
        case ItemKind::Material:
            return QObject::tr("material");
    }
    return {};
}

QString countedNoun(int count, ItemKind kind) {
    return count == 1 ? QObject::tr("1 %1").arg(kindNoun(kind))
                      : QObject::tr("%1 %2s").arg(count).arg(kindNoun(kind));
}

}  // namespace whitted::ui
