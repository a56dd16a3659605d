// ScenePanel: the three lists, their buttons and actions, and keeping a selection
// across undo, redo and list resets.
#include "panels/scene_panel.h"

#include <algorithm>

#include <QAction>
#include <QHBoxLayout>
#include <QItemSelectionModel>
#include <QLineEdit>
#include <QListView>
#include <QMenu>
#include <QPushButton>
#include <QRegularExpression>
#include <QSortFilterProxyModel>
#include <QTabWidget>
#include <QVBoxLayout>

#include "panels/material_sharing.h"
#include "panels/number_field.h"
#include "panels/scene_list_model.h"
#include "scene/material_presets.h"

namespace whitted::ui {

namespace {

constexpr std::array<ItemKind, 3> kKinds{ItemKind::Sphere, ItemKind::Light, ItemKind::Material};

bool nameTaken(const Scene& scene, ItemKind kind, const QString& name) {
    for (int i = 0; i < itemCount(scene, kind); ++i)
        if (itemName(scene, kind, i) == name) return true;
    return false;
}

// "blue ball" -> "blue ball copy", then "blue ball copy 2"; a copy of a copy
// counts on rather than growing "copy copy".
QString copyName(const Scene& scene, ItemKind kind, const QString& original) {
    static const QRegularExpression copySuffix(QStringLiteral("^(.*) copy( \\d+)?$"));
    const auto match = copySuffix.match(original);
    const QString stem = (match.hasMatch() ? match.captured(1) : original) + QObject::tr(" copy");
    if (!nameTaken(scene, kind, stem)) return stem;
    for (int n = 2;; ++n) {
        const QString candidate = QStringLiteral("%1 %2").arg(stem).arg(n);
        if (!nameTaken(scene, kind, candidate)) return candidate;
    }
}

Material defaultMaterial(const std::string& name) {
    Material m;
    m.name = name;
    m.diffuse = Vec3{0.8, 0.8, 0.8};
    m.specular = 0.5;
    m.shininess = 50.0;
    return m;
}

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

void ScenePanel::addItem(ItemKind kind) {
    const Scene& scene = doc_->scene();
    const Vec3 lookAt = scene.camera.lookAt;
    QString error;
    bool ok = false;
    switch (kind) {
        case ItemKind::Sphere: {
            const QString name = doc_->uniqueName(kind, tr("sphere"));
            const std::string newMaterial =
                doc_->uniqueName(ItemKind::Material, tr("material")).toStdString();
            ok = doc_->edit(
                tr("Add sphere %1").arg(name),
                [&](Scene& s) {
                    if (s.materials.empty()) s.materials.push_back(defaultMaterial(newMaterial));
                    Sphere sphere;
                    sphere.name = name.toStdString();
                    sphere.center = lookAt;
                    sphere.radius = 0.5;
                    sphere.material = s.materials.front().name;
                    s.spheres.push_back(std::move(sphere));
                },
                &error);
            break;
        }
        case ItemKind::Light: {
            const QString name = doc_->uniqueName(kind, tr("light"));
            ok = doc_->edit(
                tr("Add light %1").arg(name),
                [&](Scene& s) {
                    Light light;
                    light.name = name.toStdString();
                    light.position = lookAt + Vec3{2.0, 4.0, -3.0};
                    light.color = Vec3{1.0, 1.0, 1.0};
                    light.intensity = 1.0;
                    s.lights.push_back(std::move(light));
                },
                &error);
            break;
        }
        case ItemKind::Material:
            return addMaterial(nullptr);
    }
    if (!ok) {
        showRefusal(this, error);
        return;
    }
    select(kind, itemCount(doc_->scene(), kind) - 1);
}

// Add on the materials tab offers the presets, so that glass is one click away
// (a plain material is diffuse 0.8: made transparent, it still looks white).
QMenu* ScenePanel::buildAddMaterialMenu(QWidget* parent) {
    auto* menu = new QMenu(parent);
    menu->setObjectName(QStringLiteral("addMaterialMenu"));
    QAction* plain = menu->addAction(tr("Plain"), this, [this] { addMaterial(nullptr); });
    plain->setObjectName(QStringLiteral("addMaterialPlain"));
    menu->addSeparator();
    for (const MaterialPreset& preset : materialPresets()) {
        const QString name =
            QString::fromUtf8(preset.name.data(), static_cast<qsizetype>(preset.name.size()));
        QAction* action = menu->addAction(name, this, [this, &preset] { addMaterial(&preset); });
        action->setObjectName(QStringLiteral("addMaterial") + name);
    }
    return menu;
}

void ScenePanel::addMaterial(const MaterialPreset* preset) {
    const Scene& scene = doc_->scene();
    std::string name;
    if (!preset) {
        name = doc_->uniqueName(ItemKind::Material, tr("material")).toStdString();
    } else {
        // Named after its preset: "glass", then "glass 2".
        name = QString::fromUtf8(preset->name.data(), static_cast<qsizetype>(preset->name.size()))
                   .toLower()
                   .toStdString();
        if (findMaterial(scene, name) >= 0) name = numberedMaterialName(scene, name);
    }
    const Material material = preset ? presetMaterial(*preset, name) : defaultMaterial(name);
    if (!editOrTell(this, doc_, tr("Add material %1").arg(QString::fromStdString(name)),
                    [&](Scene& s) { s.materials.push_back(material); }))
        return;
    select(ItemKind::Material, itemCount(doc_->scene(), ItemKind::Material) - 1);
}

void ScenePanel::duplicateItem(ItemKind kind) {
    const int row = selectedRow(kind);
    if (row < 0) return;
    const QString original = itemName(doc_->scene(), kind, row);
    const std::string name = copyName(doc_->scene(), kind, original).toStdString();
    QString error;
    const bool ok = doc_->edit(
        tr("Duplicate %1 %2").arg(kindNoun(kind), original),
        [&](Scene& s) {
            auto copy = [&](auto& list) {
                auto item = list[row];
                item.name = name;
                list.push_back(std::move(item));
            };
            switch (kind) {
                case ItemKind::Sphere:
                    copy(s.spheres);
                    break;
                case ItemKind::Light:
                    copy(s.lights);
                    break;
                case ItemKind::Material:
                    copy(s.materials);
                    break;
            }
        },
        &error);
    if (!ok) {
        showRefusal(this, error);
        return;
    }
    select(kind, itemCount(doc_->scene(), kind) - 1);
}

void ScenePanel::deleteItem(ItemKind kind) {
    const int row = selectedRow(kind);
    if (row < 0) return;
    const int shownBefore = shownRow(kind, row);
    const Scene& scene = doc_->scene();
    const QString name = itemName(scene, kind, row);
    if (kind == ItemKind::Material) {
        // Deleting it would leave spheres naming a missing material (SPEC §6).
        const std::string material = name.toStdString();
        int users = 0;
        QString firstUser;
        for (const Sphere& sphere : scene.spheres) {
            if (sphere.material != material) continue;
            if (users++ == 0) firstUser = QString::fromStdString(sphere.name);
        }
        if (users > 0) {
            const QString who =
                users == 1 ? tr("sphere \"%1\" uses it").arg(firstUser)
                           : tr("spheres \"%1\" and %n other(s) use it", nullptr, users - 1)
                                 .arg(firstUser);
            showRefusal(this, tr("Material \"%1\" cannot be deleted: %2.\n"
                                 "Assign another material first.")
                                  .arg(name, who));
            return;
        }
    }
    QString error;
    const bool ok = doc_->edit(
        tr("Delete %1 %2").arg(kindNoun(kind), name),
        [&](Scene& s) {
            switch (kind) {
                case ItemKind::Sphere:
                    s.spheres.erase(s.spheres.begin() + row);
                    break;
                case ItemKind::Light:
                    s.lights.erase(s.lights.begin() + row);
                    break;
                case ItemKind::Material:
                    s.materials.erase(s.materials.begin() + row);
                    break;
            }
        },
        &error);
    if (!ok) {
        showRefusal(this, error);
        return;
    }
    // The next item shown takes the deleted one's place, so repeated Delete
    // walks the list (the filtered list, when there is a filter).
    Tab& t = tab(kind);
    const int next = std::min(shownBefore, t.shown->rowCount() - 1);
    tabWidget_->setCurrentIndex(static_cast<int>(kind));
    selectRow(kind, next < 0 ? -1 : t.shown->mapToSource(t.shown->index(next, 0)).row());
}

void ScenePanel::renameItem(ItemKind kind) {
    const int row = selectedRow(kind);
    if (row < 0) return;
    Tab& t = tab(kind);
    tabWidget_->setCurrentIndex(static_cast<int>(kind));
    const QModelIndex index = t.shown->index(shownRow(kind, row), 0);
    t.view->scrollTo(index);
    t.view->setFocus();
    t.view->edit(index);
}

}  // namespace whitted::ui
