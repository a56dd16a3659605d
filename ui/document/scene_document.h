// The open scene: the value the editor shows, its file, and its undo history.
//
// Every change goes through edit() or editItem() (or undo/redo), which records
// what changed (the changed items, not whole scenes) as one QUndoCommand, so
// that each edit is one undo step and a slider drag between beginGesture() and
// endGesture() is a single one.
// Listeners re-read scene() on sceneChanged(); nothing else holds scene state.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <type_traits>

#include <QObject>
#include <QString>
#include <QUndoStack>

#include "document/scene_selection.h"
#include "scene/scene.h"

namespace whitted::ui {

// Whether an edit may join the step before it: camera moves made in a run
// (arrow keys held or tapped, wheel ticks) are one undo step, not dozens.
enum class EditRun { Separate, Join };

struct SceneDelta;

class SceneDocument : public QObject {
    Q_OBJECT
  public:
    explicit SceneDocument(QObject* parent = nullptr);

    // The scene as it is now. A reference is good until the next edit.
    const Scene& scene() const { return *scene_; }
    // The scene as it is now, shared rather than copied (a million spheres
    // are 88 MB): later edits leave it as it is, since the document writes to
    // a copy while anyone else still holds it. For a render thread, which
    // reads it while the user goes on editing.
    std::shared_ptr<const Scene> snapshot() const { return scene_; }
    QString filePath() const { return filePath_; }  // empty for a new, unsaved scene
    bool isModified() const { return !undo_.isClean(); }
    // Changes whenever what a render shows may have changed: any edit, undo,
    // redo or reset but one of the render settings alone (size, samples,
    // depth, precision). A render's time speaks for the revision it showed.
    std::uint64_t contentRevision() const { return contentRevision_; }
    // Changes whenever a sphere is moved, resized, added or removed (and with
    // a new scene): what the view's marks of the selection depend on, with
    // the camera. A material or a light alone leaves it.
    std::uint64_t geometryRevision() const { return geometryRevision_; }
    QUndoStack* undoStack() { return &undo_; }
    // What is selected; emptied by reset(), following its items across edits.
    SceneSelection* selection() { return &selection_; }
    const SceneSelection* selection() const { return &selection_; }

    // Replaces the whole scene (New, Open) and forgets the undo history.
    // `validated`: the scene has passed validateScene(), as a loaded file's
    // has, so it is not checked again (a million spheres' check took 31 ms).
    void reset(Scene scene, const QString& filePath, bool validated = false);

    // Loads a file; on failure returns false with core's message in `error`
    // and leaves the current scene exactly as it was.
    bool load(const QString& path, QString* error);

    // Saves (atomically, SPEC §6) and marks the document clean. On failure
    // returns false with the reason, and the document stays modified.
    bool save(const QString& path, QString* error);

    // Applies `change` to a copy of the scene as one undoable step named `text`.
    // A change that leaves the scene invalid (validateScene) is refused: returns
    // false with the reason in `error`, and nothing happens. A change that
    // changes nothing records nothing. An EditRun::Join edit that changes
    // neither spheres, lights nor materials joins the step before it when that
    // was one too, made less than kRunGapMs earlier and not undone since
    // (the step keeps its name, or becomes "Move camera" if the names differ).
    bool edit(const QString& text, const std::function<void(Scene&)>& change,
              QString* error = nullptr, EditRun run = EditRun::Separate);
    static constexpr int kRunGapMs = 500;

    // edit() for a change to item `index` of one list alone (T is Sphere, Light
    // or Material), in time proportional to the item rather than the scene: the
    // item alone is copied, compared and validated, and its undo step built
    // directly (a property panel's edit of one of 100,000 spheres copied and
    // compared all of them). Same results, refusals, step names and signals as
    // edit() with the same change; an index out of range changes nothing. A
    // change of the item's name, the one rule between items, takes edit()'s path.
    template <class T>
    bool editItem(int index, const QString& text, const std::function<void(T&)>& change,
                  QString* error = nullptr);
    // editItem() for several items of one list at once (a change to every
    // selected sphere), one undo step, in time proportional to how many:
    // `change` is called with each item and its index. Refused as a whole
    // when any item would be invalid; names must stay as they are.
    template <class T>
    bool editItems(const std::vector<int>& indices, const QString& text,
                   const std::function<void(T&, int)>& change, QString* error = nullptr);

    // Everything edited between these two calls is a single undo step (a slider drag).
    void beginGesture(const QString& text);
    void endGesture();
    // Between beginGesture() and the end of the outermost gesture (a drag of
    // G, S or a slider): a listener may put off work over every sphere until
    // gestureEnded().
    bool inGesture() const { return gestureDepth_ > 0; }
    // Ends the gesture and forgets its step, which must leave the scene as it
    // found it: a gesture the user cancelled after its last edit put the scene
    // back (Escape during a move in the view). Nothing is left to redo. Inside
    // another gesture it only ends: the outer step keeps the cancelled edits,
    // which together change nothing.
    void discardGesture();

    // A name for a new item of `kind` that no other item of that kind has ("sphere 4").
    QString uniqueName(ItemKind kind, const QString& stem) const;

  signals:
    // An edit, undo or redo is about to write the scene, and sceneChanged()
    // follows: a holder of a snapshot that is to be replaced anyway may let
    // go of it now (the render request still waiting), so that the scene is
    // written where it lies rather than copied.
    void aboutToWrite();
    // The scene's content changed in any way (edit, undo, redo, load, new).
    void sceneChanged();
    // Items were added, removed, renamed or reordered (list models reset on it).
    void structureChanged();
    // The outermost gesture ended or was discarded: what listeners put off
    // while it lasted is due.
    void gestureEnded();
    void filePathChanged(const QString& path);
    void modifiedChanged(bool modified);

  private:
    friend class SceneEditCommand;
    void push(SceneDelta delta, const QString& text, EditRun run);
    // Changes the scene by an edit's delta, forwards or backwards, and tells listeners.
    void applyDelta(const SceneDelta& delta, bool forward);
    // The scene to write to: a copy first if a snapshot of it is still held.
    Scene& writableScene();

    std::shared_ptr<Scene> scene_ = std::make_shared<Scene>();
    QString filePath_;
    QUndoStack undo_;
    SceneSelection selection_;
    int gestureDepth_ = 0;
    bool runOpen_ = false;  // the top step is a camera run that the next Join edit may extend
    bool resetSceneValid_ = false;  // what reset() was given passed validateScene
    std::uint64_t contentRevision_ = 0;
    std::uint64_t geometryRevision_ = 0;
};

// The list of a scene (const or not like it) that holds items of type T:
// Sphere, Light or Material.
template <class T, class S>
auto& itemsOf(S& scene) {
    if constexpr (std::is_same_v<T, Sphere>)
        return scene.spheres;
    else if constexpr (std::is_same_v<T, Light>)
        return scene.lights;
    else
        return scene.materials;
}

// The number of items of a kind in a scene, and the name of item `index`.
int itemCount(const Scene& scene, ItemKind kind);
QString itemName(const Scene& scene, ItemKind kind, int index);

// The singular noun for an item kind, for messages and undo texts ("sphere").
QString kindNoun(ItemKind kind);
// A count of a kind, for messages and undo texts: "1 sphere", "3 spheres".
QString countedNoun(int count, ItemKind kind);

}  // namespace whitted::ui
