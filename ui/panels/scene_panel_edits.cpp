// ScenePanel's Add, Duplicate, Delete and Rename: each one undo step, a refusal
// shown, and the new or next item selected.
#include "panels/scene_panel.h"

#include <algorithm>
#include <string>
#include <unordered_set>
#include <vector>

#include <QAction>
#include <QListView>
#include <QMenu>
#include <QRegularExpression>
#include <QSortFilterProxyModel>
#include <QTabWidget>

#include "panels/material_sharing.h"
#include "panels/number_field.h"
#include "panels/scene_list_model.h"
#include "scene/free_spot.h"
#include "scene/material_presets.h"

namespace whitted::ui {

namespace {

// Every name of a kind, for copies to be named against.
std::unordered_set<std::string> namesOf(const Scene& scene, ItemKind kind) {
    std::unordered_set<std::string> names;
    for (int i = 0; i < itemCount(scene, kind); ++i) names.insert(itemNameOf(scene, kind, i));
    return names;
}

// "blue ball" -> "blue ball copy", then "blue ball copy 2"; a copy of a copy
// counts on rather than growing "copy copy". The name is added to `taken`.
std::string copyName(std::unordered_set<std::string>& taken, const QString& original) {
    static const QRegularExpression copySuffix(QStringLiteral("^(.*) copy( \\d+)?$"));
    const auto match = copySuffix.match(original);
    const QString stem = (match.hasMatch() ? match.captured(1) : original) + QObject::tr(" copy");
    std::string name = stem.toStdString();
    for (int n = 2; taken.contains(name); ++n)
        name = QStringLiteral("%1 %2").arg(stem).arg(n).toStdString();
    taken.insert(name);
    return name;
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

void ScenePanel::addSphere(std::optional<Vec3> centre) {
    const QString name = doc_->uniqueName(ItemKind::Sphere, tr("sphere"));
    const std::string newMaterial =
        doc_->uniqueName(ItemKind::Material, tr("material")).toStdString();
    QString error;
    const bool ok = doc_->edit(
        tr("Add sphere %1").arg(name),
        [&](Scene& s) {
            if (s.materials.empty()) s.materials.push_back(defaultMaterial(newMaterial));
            Sphere sphere;
            sphere.name = name.toStdString();
            sphere.radius = kNewSphereRadius;
            sphere.center = centre.value_or(freeSpotForSphere(s, sphere.radius));
            sphere.material = s.materials.front().name;
            s.spheres.push_back(std::move(sphere));
        },
        &error);
    if (!ok) {
        showRefusal(this, error);
        return;
    }
    select(ItemKind::Sphere, itemCount(doc_->scene(), ItemKind::Sphere) - 1);
}

void ScenePanel::addItem(ItemKind kind) {
    const Scene& scene = doc_->scene();
    const Vec3 lookAt = scene.camera.lookAt;
    QString error;
    bool ok = false;
    switch (kind) {
        case ItemKind::Sphere:
            if (!addSphereHere_ || !addSphereHere_()) addSphere({});
            return;
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

namespace {

// Every item of `list` at `rows` (ascending), copied to the end under `names`.
template <class T>
void appendCopies(std::vector<T>& list, const std::vector<int>& rows,
                  const std::vector<std::string>& names) {
    for (std::size_t k = 0; k < rows.size(); ++k) {
        T item = list[rows[k]];
        item.name = names[k];
        list.push_back(std::move(item));
    }
}

// `list` without the items at `rows` (ascending).
template <class T>
void eraseRows(std::vector<T>& list, const std::vector<int>& rows) {
    std::vector<T> kept;
    kept.reserve(list.size() - rows.size());
    std::size_t next = 0;
    for (std::size_t i = 0; i < list.size(); ++i) {
        if (next < rows.size() && rows[next] == static_cast<int>(i)) {
            ++next;
            continue;
        }
        kept.push_back(std::move(list[i]));
    }
    list = std::move(kept);
}

// "blue ball" for one item, "3 spheres" for several: what an undo step names.
QString whatIsSelected(const Scene& scene, ItemKind kind, const std::vector<int>& rows) {
    if (rows.size() == 1) return kindNoun(kind) + QLatin1Char(' ') + itemName(scene, kind, rows[0]);
    return countedNoun(int(rows.size()), kind);
}

}  // namespace

void ScenePanel::duplicateItem(ItemKind kind) {
    const std::vector<int> rows = selectedRows(kind);
    if (rows.empty()) return;
    const Scene& scene = doc_->scene();
    const int count = itemCount(scene, kind);
    std::unordered_set<std::string> taken = namesOf(scene, kind);
    std::vector<std::string> names;
    for (int row : rows) names.push_back(copyName(taken, itemName(scene, kind, row)));
    const bool ok = editOrTell(
        this, doc_, tr("Duplicate %1").arg(whatIsSelected(scene, kind, rows)), [&](Scene& s) {
            switch (kind) {
                case ItemKind::Sphere:
                    return appendCopies(s.spheres, rows, names);
                case ItemKind::Light:
                    return appendCopies(s.lights, rows, names);
                case ItemKind::Material:
                    return appendCopies(s.materials, rows, names);
            }
        });
    if (!ok) return;
    std::vector<int> copies(rows.size());
    for (std::size_t k = 0; k < rows.size(); ++k) copies[k] = count + static_cast<int>(k);
    doc_->selection()->set(kind, std::move(copies));
}

// Materials that spheres use cannot go (SPEC §6): the refusal names one user.
bool ScenePanel::materialsInUse(const std::vector<int>& rows) {
    const Scene& scene = doc_->scene();
    for (int row : rows) {
        const std::string& material = scene.materials[row].name;
        int users = 0;
        QString firstUser;
        for (const Sphere& sphere : scene.spheres) {
            if (sphere.material != material) continue;
            if (users++ == 0) firstUser = QString::fromStdString(sphere.name);
        }
        if (users == 0) continue;
        const QString who =
            users == 1
                ? tr("sphere \"%1\" uses it").arg(firstUser)
                : tr("spheres \"%1\" and %n other(s) use it", nullptr, users - 1).arg(firstUser);
        showRefusal(this, tr("Material \"%1\" cannot be deleted: %2.\n"
                             "Assign another material first.")
                              .arg(QString::fromStdString(material), who));
        return true;
    }
    return false;
}

void ScenePanel::deleteItem(ItemKind kind) {
    const std::vector<int> rows = selectedRows(kind);
    if (rows.empty()) return;
    if (kind == ItemKind::Material && materialsInUse(rows)) return;
    const int shownBefore = shownRow(kind, rows.front());
    const bool ok = editOrTell(
        this, doc_, tr("Delete %1").arg(whatIsSelected(doc_->scene(), kind, rows)), [&](Scene& s) {
            switch (kind) {
                case ItemKind::Sphere:
                    return eraseRows(s.spheres, rows);
                case ItemKind::Light:
                    return eraseRows(s.lights, rows);
                case ItemKind::Material:
                    return eraseRows(s.materials, rows);
            }
        });
    if (!ok) return;
    // The next item shown takes the first deleted one's place, so repeated
    // Delete walks the list (the filtered list, when there is a filter).
    Tab& t = tab(kind);
    const int next = std::min(shownBefore, t.shown->rowCount() - 1);
    select(kind, next < 0 ? -1 : t.shown->mapToSource(t.shown->index(next, 0)).row());
}

void ScenePanel::renameItem(ItemKind kind) {
    const int row = doc_->selection()->kind() == kind ? doc_->selection()->active() : -1;
    if (row < 0) return;
    Tab& t = tab(kind);
    tabWidget_->setCurrentIndex(static_cast<int>(kind));
    const QModelIndex index = t.shown->index(shownRow(kind, row), 0);
    t.view->scrollTo(index);
    t.view->setFocus();
    t.view->edit(index);
}

}  // namespace whitted::ui
