// The scene panel (for a dock): tabs listing spheres, lights and materials, with
// Add, Duplicate, Delete and Rename, each one undo step.
#pragma once

#include <array>
#include <functional>
#include <optional>

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

    // Switches to the kind's tab, selects row `index` and scrolls to it; -1 clears
    // the tab's selection. Emits selectionChanged when that changes what is selected.
    void select(ItemKind kind, int index);
    ItemKind currentKind() const;
    int currentIndex() const;  // -1 when nothing is selected in the current tab

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
    QAction* deleteAction() const { return deleteAction_; }
    QAction* renameAction() const { return renameAction_; }

  signals:
    void selectionChanged(whitted::ui::ItemKind kind, int index);  // index -1: none

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
        // What was selected, to find it again after the list is reset.
        int selectedRow = -1;
        QString selectedName;
    };

    Tab& tab(ItemKind kind) { return tabs_[static_cast<int>(kind)]; }
    const Tab& tab(ItemKind kind) const { return tabs_[static_cast<int>(kind)]; }
    int selectedRow(ItemKind kind) const;
    void buildTab(ItemKind kind, const QString& title, const QString& listName);
    QHBoxLayout* buildTabButtons(ItemKind kind, QWidget* page);
    void selectRow(ItemKind kind, int row);
    void setFilter(ItemKind kind, const QString& text);
    int shownRow(ItemKind kind, int row) const;
    void onViewSelectionChanged(ItemKind kind);
    void restoreSelection(ItemKind kind);
    void updateEnabled();
    void announce();

    // scene_panel_edits.cpp
    void addItem(ItemKind kind);
    QMenu* buildAddMaterialMenu(QWidget* parent);
    void addMaterial(const MaterialPreset* preset);  // nullptr: a plain material
    void duplicateItem(ItemKind kind);
    void deleteItem(ItemKind kind);
    void renameItem(ItemKind kind);

    SceneDocument* doc_;
    QTabWidget* tabWidget_;
    std::array<Tab, 3> tabs_;
    QAction* addAction_;
    QAction* duplicateAction_;
    std::function<bool()> addSphereHere_;
    QAction* deleteAction_;
    QAction* renameAction_;
    ItemKind announcedKind_ = ItemKind::Sphere;
    int announcedIndex_ = -2;  // nothing announced yet
};

}  // namespace whitted::ui
