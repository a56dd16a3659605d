// ScenePanel's Add, Duplicate, Delete and Rename: each one undo step, a refusal
// shown, and the new or next item selected.
#include "panels/scene_panel.h"

#include <algorithm>

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
