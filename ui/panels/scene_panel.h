// The scene panel (for a dock): tabs listing spheres, lights and materials, with
// Add, Duplicate, Delete and Rename, each one undo step. The lists show the
// document's selection (SceneSelection) and set it: a click selects one item,
// Shift+click a range, Ctrl+click adds or removes one. Duplicate and Delete act
// on every selected item, Rename on the active one.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <vector>

#include <QWidget>

#include "document/scene_document.h"

class QAction;
class QHBoxLayout;
class QLineEdit;
class QListView;
class QSortFilterProxyModel;
class QMenu;
class QPushButton;
class QTabWidget;

namespace whitted {
struct MaterialPreset;
}

namespace whitted::ui {

class SceneListModel;

class ScenePanel : public QWidget {
    Q_OBJECT
  public:
    explicit ScenePanel(SceneDocument* doc, QWidget* parent = nullptr);

    // Selects item `index` of the kind alone (-1: nothing), shows its tab and
    // scrolls to it. Emits selectionChanged when the active item changes.
    void select(ItemKind kind, int index);
    ItemKind currentKind() const;  // the tab shown
    // The active item of the selection, when it is of the tab shown; else -1.
    int currentIndex() const;

    // For the Edit menu: the buttons' behaviour on the current tab. Their shortcuts
    // (Ctrl+D, Delete, F2) work once the window holds the actions, e.g. in a menu.
    QAction* addAction() const { return addAction_; }

    // A new sphere, of radius kNewSphereRadius, at `centre`, or where the camera
    // looks (a free spot beside what is there); selected. One undo step.
    void addSphere(std::optional<Vec3> centre);
    static constexpr double kNewSphereRadius = 0.5;
    // What Add does on the Spheres tab first: a handler that places the sphere
    // itself (the window's: where the user points in the view) and returns
    // true, or returns false to leave it to addSphere({}).
    void setAddSphereHere(std::function<bool()> handler) { addSphereHere_ = std::move(handler); }
    QAction* duplicateAction() const { return duplicateAction_; }
    // Copies every selected item of `kind`, named "<name> copy", and selects
    // the copies. One undo step.
    void duplicateItem(ItemKind kind);
    QAction* deleteAction() const { return deleteAction_; }
    QAction* renameAction() const { return renameAction_; }

  signals:
    // The active item changed (index -1: none).
    void selectionChanged(whitted::ui::ItemKind kind, int index);

  private:
    struct Tab {
        SceneListModel* model = nullptr;
        // What the view shows: the model's rows whose names contain the
        // filter's text. Rows in this panel's interface are always the
        // model's (the scene's indices); only the view sees filtered ones.
        QSortFilterProxyModel* shown = nullptr;
        QLineEdit* filter = nullptr;
        QListView* view = nullptr;
        QPushButton* duplicate = nullptr;
        QPushButton* remove = nullptr;
        QPushButton* rename = nullptr;
    };

    Tab& tab(ItemKind kind) { return tabs_[static_cast<int>(kind)]; }
    const Tab& tab(ItemKind kind) const { return tabs_[static_cast<int>(kind)]; }
    // The selected items of a tab's kind (none when the selection is of another).
    std::vector<int> selectedRows(ItemKind kind) const;
    void buildTab(ItemKind kind, const QString& title, const QString& listName);
    QHBoxLayout* buildTabButtons(ItemKind kind, QWidget* page);
    void setFilter(ItemKind kind, const QString& text);
    int shownRow(ItemKind kind, int row) const;
    // The user changed a list's selection: it becomes the document's.
    void onViewSelectionChanged(ItemKind kind);
    // The document's selection changed: the lists show it.
    void showSelection();
    void showSelectionIn(ItemKind kind);
    void updateEnabled();
    void announce();

    // scene_panel_edits.cpp
    void addItem(ItemKind kind);
    QMenu* buildAddMaterialMenu(QWidget* parent);
    void addMaterial(const MaterialPreset* preset);  // nullptr: a plain material
    void deleteItem(ItemKind kind);
    // True, with the refusal shown, when a sphere uses one of these materials.
    bool materialsInUse(const std::vector<int>& rows);
    void renameItem(ItemKind kind);

    SceneDocument* doc_;
    QTabWidget* tabWidget_;
    std::array<Tab, 3> tabs_;
    QAction* addAction_;
    QAction* duplicateAction_;
    std::function<bool()> addSphereHere_;
    QAction* deleteAction_;
    QAction* renameAction_;
    bool showing_ = false;  // showSelection() is setting the lists' selections
    ItemKind announcedKind_ = ItemKind::Sphere;
    int announcedIndex_ = -2;  // nothing announced yet
};

}  // namespace whitted::ui
