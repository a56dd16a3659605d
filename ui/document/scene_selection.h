// What the user has selected: any number of items of one kind (spheres, lights
// or materials), and of them the active one, the last clicked, whose
// properties the panel shows and which F frames. The list, the view and the
// property panel all read and set this one value, so they cannot disagree.
// It follows its items by name across edits that add, remove, rename or
// reorder them (undo of a delete included), and drops what is gone.
#pragma once

#include <string>
#include <vector>

#include <QObject>

#include "scene/scene.h"

namespace whitted::ui {

enum class ItemKind { Sphere, Light, Material };

class SceneSelection : public QObject {
    Q_OBJECT
  public:
    using QObject::QObject;

    ItemKind kind() const { return kind_; }
    // The selected items' indices, ascending; empty when nothing is selected.
    const std::vector<int>& indices() const { return indices_; }
    int count() const { return static_cast<int>(indices_.size()); }
    bool empty() const { return indices_.empty(); }
    // The active item: one of indices(), or -1 when nothing is selected.
    int active() const { return active_; }
    bool contains(ItemKind kind, int index) const;

    // Replaces the selection (indices in any order, repeats ignored). The
    // active item is `active` when selected, else the last of `indices`.
    void set(ItemKind kind, std::vector<int> indices, int active = -1);
    // One item alone; index -1 selects nothing of that kind.
    void selectOne(ItemKind kind, int index);
    // Shift+click: adds the item, or removes it when it was selected. Another
    // kind than the selection's starts a new selection.
    void toggle(ItemKind kind, int index);
    void clear() { set(kind_, {}); }

    // The whole selection as a value: undo puts back the one an edit found,
    // so that undoing a delete selects what comes back.
    struct Snapshot {
        ItemKind kind = ItemKind::Sphere;
        std::vector<int> indices;
        int active = -1;
    };
    Snapshot snapshot() const { return {kind_, indices_, active_}; }
    void restore(const Snapshot& s) { set(s.kind, s.indices, s.active); }

    // Called by the document around a change that adds, removes, renames or
    // reorders items: the names before, and the scene after.
    void rememberNames(const Scene& before);
    void followNames(const Scene& after);

  signals:
    void changed();

  private:
    ItemKind kind_ = ItemKind::Sphere;
    std::vector<int> indices_;
    int active_ = -1;
    std::vector<std::string> names_;  // of indices_, while a change is made
    std::string activeName_;
    int countBefore_ = 0;  // of the selection's kind, while a change is made
};

// The name of item `index` of a kind, or an empty string.
const std::string& itemNameOf(const Scene& scene, ItemKind kind, int index);

}  // namespace whitted::ui
