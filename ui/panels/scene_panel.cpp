// ScenePanel: the three lists, their buttons and actions, and keeping a selection
// across undo, redo and list resets. What the buttons do to the scene is in
// scene_panel_edits.cpp.
#include "panels/scene_panel.h"

#include <algorithm>

#include <QAction>
#include <QHBoxLayout>
#include <QItemSelectionModel>
#include <QLineEdit>
#include <QListView>
#include <QPushButton>
#include <QSortFilterProxyModel>
#include <QTabWidget>
#include <QVBoxLayout>

#include "panels/number_field.h"
#include "panels/scene_list_model.h"

namespace whitted::ui {

namespace {

constexpr std::array<ItemKind, 3> kKinds{ItemKind::Sphere, ItemKind::Light, ItemKind::Material};

}  // namespace

ScenePanel::ScenePanel(SceneDocument* doc, QWidget* parent)
    : QWidget(parent), doc_(doc), tabWidget_(new QTabWidget(this)) {
    tabWidget_->setObjectName(QStringLiteral("sceneTabs"));
    tabWidget_->setDocumentMode(true);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(tabWidget_);

    addAction_ = new QAction(tr("&Add"), this);
    addAction_->setObjectName(QStringLiteral("addAction"));
    addAction_->setStatusTip(tr("Add a new item to the current list"));
    // Blender's key for adding. A text field keeps it as a capital A.
    addAction_->setShortcut(QKeySequence(tr("Shift+A")));
    duplicateAction_ = new QAction(tr("D&uplicate"), this);
    duplicateAction_->setObjectName(QStringLiteral("duplicateAction"));
    duplicateAction_->setShortcut(QKeySequence(tr("Ctrl+D")));
    deleteAction_ = new QAction(tr("&Delete"), this);
    deleteAction_->setObjectName(QStringLiteral("deleteAction"));
    deleteAction_->setShortcut(QKeySequence::Delete);
    renameAction_ = new QAction(tr("Re&name"), this);
    renameAction_->setObjectName(QStringLiteral("renameAction"));
    renameAction_->setShortcut(QKeySequence(Qt::Key_F2));
    connect(addAction_, &QAction::triggered, this, [this] { addItem(currentKind()); });
    connect(duplicateAction_, &QAction::triggered, this, [this] { duplicateItem(currentKind()); });
    connect(deleteAction_, &QAction::triggered, this, [this] { deleteItem(currentKind()); });
    connect(renameAction_, &QAction::triggered, this, [this] { renameItem(currentKind()); });

    buildTab(ItemKind::Sphere, tr("Spheres"), QStringLiteral("sphereList"));
    buildTab(ItemKind::Light, tr("Lights"), QStringLiteral("lightList"));
    buildTab(ItemKind::Material, tr("Materials"), QStringLiteral("materialList"));

    connect(tabWidget_, &QTabWidget::currentChanged, this, [this] {
        updateEnabled();
        announce();
    });
    updateEnabled();
}

void ScenePanel::buildTab(ItemKind kind, const QString& title, const QString& listName) {
    Tab& t = tab(kind);
    auto* page = new QWidget;
    page->setObjectName(listName + QStringLiteral("Page"));
    t.model = new SceneListModel(doc_, kind, this);
    t.shown = new QSortFilterProxyModel(this);
    t.shown->setSourceModel(t.model);
    t.shown->setFilterCaseSensitivity(Qt::CaseInsensitive);
    t.filter = new QLineEdit(page);
    t.filter->setObjectName(listName + QStringLiteral("Filter"));
    t.filter->setPlaceholderText(tr("Filter by name"));
    t.filter->setClearButtonEnabled(true);
    t.filter->setToolTip(tr("Show only the %1s whose names contain this text").arg(kindNoun(kind)));
    connect(t.filter, &QLineEdit::textChanged, this,
            [this, kind](const QString& text) { setFilter(kind, text); });
    t.view = new QListView(page);
    t.view->setObjectName(listName);
    t.view->setModel(t.shown);
    // Uniform sizes let the view lay out 100,000 rows without measuring each one.
    t.view->setUniformItemSizes(true);
    t.view->setSelectionMode(QAbstractItemView::SingleSelection);
    t.view->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                            QAbstractItemView::SelectedClicked);
    QHBoxLayout* buttons = buildTabButtons(kind, page);
    auto* layout = new QVBoxLayout(page);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(t.filter);
    layout->addWidget(t.view);
    layout->addLayout(buttons);
    tabWidget_->addTab(page, title);

    connect(t.view->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            [this, kind] { onViewSelectionChanged(kind); });
    connect(t.model, &QAbstractItemModel::modelReset, this,
            [this, kind] { restoreSelection(kind); });
    connect(t.model, &SceneListModel::editRefused, this,
            [this](const QString& reason) { showRefusal(this, reason); });
}

QHBoxLayout* ScenePanel::buildTabButtons(ItemKind kind, QWidget* page) {
    Tab& t = tab(kind);
    auto button = [page](const QString& text, const QString& name, const QString& tip) {
        auto* b = new QPushButton(text, page);
        b->setObjectName(name);
        b->setToolTip(tip);
        b->setAutoDefault(false);
        return b;
    };
    const QString noun = kindNoun(kind);
    auto* add = button(tr("Add"), QStringLiteral("addButton"), tr("Add a new %1").arg(noun));
    t.duplicate = button(tr("Duplicate"), QStringLiteral("duplicateButton"),
                         tr("Copy the selected %1").arg(noun));
    t.remove = button(tr("Delete"), QStringLiteral("deleteButton"),
                      tr("Delete the selected %1").arg(noun));
    t.rename = button(tr("Rename"), QStringLiteral("renameButton"),
                      tr("Rename the selected %1").arg(noun));
    // Each tab's buttons act on their own list, whichever tab is showing.
    if (kind == ItemKind::Material)
        add->setMenu(buildAddMaterialMenu(add));
    else
        connect(add, &QPushButton::clicked, this, [this, kind] { addItem(kind); });
    connect(t.duplicate, &QPushButton::clicked, this, [this, kind] { duplicateItem(kind); });
    connect(t.remove, &QPushButton::clicked, this, [this, kind] { deleteItem(kind); });
    connect(t.rename, &QPushButton::clicked, this, [this, kind] { renameItem(kind); });

    auto* buttons = new QHBoxLayout;
    buttons->setSpacing(4);
    for (QPushButton* b : {add, t.duplicate, t.remove, t.rename}) buttons->addWidget(b);
    return buttons;
}

ItemKind ScenePanel::currentKind() const {
    const int i = tabWidget_->currentIndex();
    return i >= 0 && i < static_cast<int>(kKinds.size()) ? kKinds[i] : ItemKind::Sphere;
}

int ScenePanel::currentIndex() const {
    return selectedRow(currentKind());
}

int ScenePanel::selectedRow(ItemKind kind) const {
    const Tab& t = tab(kind);
    const QModelIndexList rows = t.view->selectionModel()->selectedRows();
    return rows.isEmpty() ? -1 : t.shown->mapToSource(rows.first()).row();
}

// A selected item the filter hides is deselected (the buttons and the Edit
// menu act only on what the list shows); one it keeps stays selected, in view.
void ScenePanel::setFilter(ItemKind kind, const QString& text) {
    Tab& t = tab(kind);
    const int selected = t.selectedRow;
    t.shown->setFilterFixedString(text);
    selectRow(kind, selected);
}

// The row in the list as shown, or -1 when the filter hides it.
int ScenePanel::shownRow(ItemKind kind, int row) const {
    const Tab& t = tab(kind);
    return row < 0 ? -1 : t.shown->mapFromSource(t.model->index(row)).row();
}

// What is selected from elsewhere (a click in the picture, a new item) must be
// seen: a filter that hides it is cleared.
void ScenePanel::select(ItemKind kind, int index) {
    tabWidget_->setCurrentIndex(static_cast<int>(kind));
    Tab& t = tab(kind);
    if (index >= 0 && index < t.model->rowCount() && shownRow(kind, index) < 0) t.filter->clear();
    selectRow(kind, index);
}

void ScenePanel::selectRow(ItemKind kind, int row) {
    Tab& t = tab(kind);
    const int shown = row < t.model->rowCount() ? shownRow(kind, row) : -1;
    if (shown < 0) {
        t.view->selectionModel()->clear();
        onViewSelectionChanged(kind);  // clear() does not always report an empty selection
        return;
    }
    const QModelIndex index = t.shown->index(shown, 0);
    t.view->selectionModel()->setCurrentIndex(index, QItemSelectionModel::ClearAndSelect);
    t.view->scrollTo(index);
}

void ScenePanel::onViewSelectionChanged(ItemKind kind) {
    Tab& t = tab(kind);
    t.selectedRow = selectedRow(kind);
    t.selectedName = itemName(doc_->scene(), kind, t.selectedRow);
    updateEnabled();
    if (kind == currentKind()) announce();
}

void ScenePanel::restoreSelection(ItemKind kind) {
    // A reset drops the selection silently. Follow the item by name (undo of a
    // delete elsewhere moves it), else keep the row, else select nothing.
    Tab& t = tab(kind);
    int row = -1;
    if (!t.selectedName.isEmpty()) {
        for (int i = 0; i < itemCount(doc_->scene(), kind) && row < 0; ++i)
            if (itemName(doc_->scene(), kind, i) == t.selectedName) row = i;
        if (row < 0 && t.selectedRow < itemCount(doc_->scene(), kind)) row = t.selectedRow;
    }
    selectRow(kind, row);
}

void ScenePanel::updateEnabled() {
    for (ItemKind kind : kKinds) {
        Tab& t = tab(kind);
        const bool any = selectedRow(kind) >= 0;
        t.duplicate->setEnabled(any);
        t.remove->setEnabled(any);
        t.rename->setEnabled(any);
    }
    const bool any = currentIndex() >= 0;
    duplicateAction_->setEnabled(any);
    deleteAction_->setEnabled(any);
    renameAction_->setEnabled(any);
}

void ScenePanel::announce() {
    const ItemKind kind = currentKind();
    const int index = currentIndex();
    if (kind == announcedKind_ && index == announcedIndex_) return;
    announcedKind_ = kind;
    announcedIndex_ = index;
    emit selectionChanged(kind, index);
}

}  // namespace whitted::ui
