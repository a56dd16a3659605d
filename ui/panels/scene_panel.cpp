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
#include <QScopedValueRollback>
#include <QSignalBlocker>
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

    connect(tabWidget_, &QTabWidget::currentChanged, this, [this] { updateEnabled(); });
    connect(doc_->selection(), &SceneSelection::changed, this, &ScenePanel::showSelection);
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
    t.view->setSelectionMode(QAbstractItemView::ExtendedSelection);
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
    // A reset drops the list's selection; the document's followed its items.
    connect(t.model, &QAbstractItemModel::modelReset, this,
            [this, kind] { showSelectionIn(kind); });
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
    const SceneSelection* selection = doc_->selection();
    return selection->kind() == currentKind() ? selection->active() : -1;
}

std::vector<int> ScenePanel::selectedRows(ItemKind kind) const {
    const SceneSelection* selection = doc_->selection();
    return selection->kind() == kind ? selection->indices() : std::vector<int>{};
}

// A selected item the filter hides is deselected (the buttons and the Edit
// menu act only on what the list shows); one it keeps stays selected, in view.
void ScenePanel::setFilter(ItemKind kind, const QString& text) {
    tab(kind).shown->setFilterFixedString(text);
    SceneSelection* selection = doc_->selection();
    if (selection->kind() != kind) return;
    std::vector<int> kept;
    for (int row : selection->indices())
        if (shownRow(kind, row) >= 0) kept.push_back(row);
    selection->set(kind, std::move(kept), selection->active());
    showSelectionIn(kind);
}

// The row in the list as shown, or -1 when the filter hides it.
int ScenePanel::shownRow(ItemKind kind, int row) const {
    const Tab& t = tab(kind);
    if (row < 0) return -1;
    // Unfiltered, the rows are the model's: mapping 100,000 selected rows
    // through the proxy took 20 ms of a box selection.
    if (t.filter->text().isEmpty()) return row < t.model->rowCount() ? row : -1;
    return t.shown->mapFromSource(t.model->index(row)).row();
}

void ScenePanel::select(ItemKind kind, int index) {
    tabWidget_->setCurrentIndex(static_cast<int>(kind));
    if (index >= itemCount(doc_->scene(), kind)) index = -1;
    doc_->selection()->selectOne(kind, index);
    showSelectionIn(kind);  // scrolled to, even when it was selected already
}

void ScenePanel::onViewSelectionChanged(ItemKind kind) {
    if (showing_) return;
    const Tab& t = tab(kind);
    std::vector<int> rows;
    for (const QModelIndex& index : t.view->selectionModel()->selectedRows())
        rows.push_back(t.shown->mapToSource(index).row());
    const QModelIndex current = t.view->selectionModel()->currentIndex();
    const int active = current.isValid() ? t.shown->mapToSource(current).row() : -1;
    // Emptying another tab's list leaves the selection of this kind alone.
    if (rows.empty() && doc_->selection()->kind() != kind) return;
    doc_->selection()->set(kind, std::move(rows), active);
}

void ScenePanel::showSelection() {
    const ItemKind kind = doc_->selection()->kind();
    // What is selected from elsewhere (a click in the picture, a new item) is shown.
    if (!doc_->selection()->empty()) tabWidget_->setCurrentIndex(static_cast<int>(kind));
    for (ItemKind k : kKinds) showSelectionIn(k);
    updateEnabled();
    announce();
}

void ScenePanel::showSelectionIn(ItemKind kind) {
    Tab& t = tab(kind);
    const std::vector<int> rows = selectedRows(kind);
    // A filter that hides a selected item is cleared, so that it can be seen.
    for (int row : rows)
        if (shownRow(kind, row) < 0) {
            const QSignalBlocker block(t.filter);
            t.filter->clear();
            t.shown->setFilterFixedString(QString());
            break;
        }
    // Runs of neighbouring rows as one range each: a box of 100,000 spheres
    // is far fewer ranges than rows when the scene lists them in order.
    QItemSelection ranges;
    int first = -1, last = -1;
    auto flush = [&] {
        if (first >= 0) ranges.select(t.shown->index(first, 0), t.shown->index(last, 0));
    };
    for (int row : rows) {
        const int shown = shownRow(kind, row);
        if (shown == last + 1 && first >= 0) {
            last = shown;
            continue;
        }
        flush();
        first = last = shown;
    }
    flush();
    const QScopedValueRollback<bool> showing(showing_, true);
    QItemSelectionModel* model = t.view->selectionModel();
    model->select(ranges, QItemSelectionModel::ClearAndSelect);
    const int active = doc_->selection()->kind() == kind ? doc_->selection()->active() : -1;
    if (active >= 0) {
        const QModelIndex index = t.shown->index(shownRow(kind, active), 0);
        model->setCurrentIndex(index, QItemSelectionModel::NoUpdate);
        t.view->scrollTo(index);
    }
}

void ScenePanel::updateEnabled() {
    for (ItemKind kind : kKinds) {
        Tab& t = tab(kind);
        const bool any = !selectedRows(kind).empty();
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
    const ItemKind kind = doc_->selection()->kind();
    const int index = doc_->selection()->active();
    if (kind == announcedKind_ && index == announcedIndex_) return;
    announcedKind_ = kind;
    announcedIndex_ = index;
    emit selectionChanged(kind, index);
}

}  // namespace whitted::ui
