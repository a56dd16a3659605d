#include "panels/sphere_page.h"

#include <algorithm>
#include <cmath>

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>

#include "document/field_words.h"
#include "panels/material_rows.h"
#include "panels/material_sharing.h"
#include "panels/panel_fields.h"

namespace whitted::ui {

namespace {

// The centre's arrow step: the power of ten nearest a tenth of the radius, so a
// 0.05 marble moves by 0.01 and the seed's 0.6 balls by 0.1 (a fixed 0.1 moved
// the marble by its own diameter).
double centreStep(double radius) {
    if (!(radius > 0.0) || !std::isfinite(radius)) return 0.1;
    return std::pow(10.0, std::round(std::log10(radius / 10.0)));
}

}  // namespace

SpherePage::SpherePage(SceneDocument* doc, QWidget* parent)
    : QWidget(parent), doc_(doc), name_(makeNameLabel(QStringLiteral("sphereName"))) {
    setObjectName(QStringLiteral("spherePage"));
    QFormLayout* form = makeForm(this);
    auto sphere = [this](auto& s) { return itemAt(s.spheres, index_); };
    const Targets targets = [this](const Scene&) { return this->targets(); };
    auto text = [this](const QString& what) {
        return [this, what] { return tr("Change %1 of %2").arg(what, sphereName()); };
    };

    form->addRow(tr("Sphere:"), name_);
    const DoubleFieldSpec centre = kCoordinate.stepFrom([sphere](const Scene& s) {
        const Sphere* sp = sphere(s);
        return centreStep(sp ? sp->radius : 1.0);
    });
    form->addRow(fieldRow(scene_field::kCentre),
                 makeItemsVectorRow<Sphere>(
                     doc_, QStringLiteral("sphereCenter"), centre, targets,
                     [](auto& sp) { return &sp.center; }, text(fieldChanged(scene_field::kCentre)),
                     fields_));
    form->addRow(fieldRow(scene_field::kRadius),
                 makeItemsField<Sphere>(
                     doc_, QStringLiteral("sphereRadius"), kLength, targets,
                     [](auto& sp) { return &sp.radius; }, text(fieldChanged(scene_field::kRadius)),
                     fields_));
    form->addRow(fieldRow(scene_field::kSphereMaterial), buildMaterialChoice());
    form->addRow(QString(), users_);  // "Shared by 3 spheres" says what it is
    materialRows_ = std::make_unique<MaterialRows>(
        doc_, this, form, MaterialRows::Extent::Main, QStringLiteral("sphereMaterial"),
        [this](const Scene&) { return materials_; },
        [this](const QString& what) {
            return tr("Change %1 of material %2").arg(what, materialName());
        });
}

SpherePage::~SpherePage() = default;

QWidget* SpherePage::buildMaterialChoice() {
    auto* row = new QWidget;
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    material_ = new QComboBox;
    material_->setObjectName(QStringLiteral("sphereMaterial"));
    material_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    material_->setMinimumContentsLength(12);
    connect(material_, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (i < 0 || i >= static_cast<int>(doc_->scene().materials.size())) return;
        const std::string material = doc_->scene().materials[i].name;
        if (!editItemsOrTell<Sphere>(this, doc_, targets(),
                                     tr("Change material of %1").arg(sphereName()),
                                     [material](Sphere& sp) { sp.material = material; }))
            refresh();
    });
    makeUnique_ = new QPushButton(tr("Make unique"));
    makeUnique_->setObjectName(QStringLiteral("sphereMakeUnique"));
    makeUnique_->setToolTip(
        tr("Give this sphere its own copy of the material, so that editing it here changes "
           "no other sphere"));
    connect(makeUnique_, &QPushButton::clicked, this, [this] {
        editOrTell(this, doc_, tr("Make material of %1 unique").arg(sphereName()),
                   [this](Scene& s) { makeMaterialUnique(s, index_); });
    });
    layout->addWidget(material_, 1);
    layout->addWidget(makeUnique_);

    users_ = new QLabel;
    users_->setObjectName(QStringLiteral("sphereMaterialUsers"));
    users_->setToolTip(tr("How many spheres this material's settings change"));
    return row;
}

void SpherePage::setIndex(int index) {
    index_ = index;
    refresh();
}

std::vector<int> SpherePage::materialTargets(const Scene& scene) const {
    std::vector<int> materials;
    const std::string* last = nullptr;  // neighbours mostly share a material
    for (int i : editTargets(*doc_, ItemKind::Sphere, index_)) {
        const Sphere* sphere = itemAt(scene.spheres, i);
        if (!sphere || (last && sphere->material == *last)) continue;
        last = &sphere->material;
        const int m = findMaterial(scene, sphere->material);
        if (m >= 0 && std::find(materials.begin(), materials.end(), m) == materials.end())
            materials.push_back(m);
    }
    return materials;
}

std::vector<int> SpherePage::targets() const {
    return editTargets(*doc_, ItemKind::Sphere, index_);
}

QString SpherePage::sphereName() const {
    const std::size_t others = targets().size() - 1;
    const QString name = itemName(doc_->scene(), ItemKind::Sphere, index_);
    return others == 0 ? name : tr("%1 (and %2 more)").arg(name).arg(others);
}

QString SpherePage::materialName() const {
    const std::vector<int>& materials = materials_;
    const QString name =
        itemName(doc_->scene(), ItemKind::Material, materials.empty() ? -1 : materials.front());
    return materials.size() <= 1 ? name
                                 : tr("%1 (and %2 more)").arg(name).arg(materials.size() - 1);
}

void SpherePage::refresh() {
    const Sphere* sphere = itemAt(doc_->scene().spheres, index_);
    if (!sphere) return;
    // Once a refresh, for all the rows: found afresh, a selection of 100,000
    // spheres took 5 ms each time, a dozen times a refresh.
    materials_ = materialTargets(doc_->scene());
    name_->setText(sphereName());
    refreshAll(fields_);
    refreshMaterialChoice(*sphere);
    materialRows_->refresh();
}

void SpherePage::refreshMaterialChoice(const Sphere& sphere) {
    const Scene& scene = doc_->scene();
    {
        const QSignalBlocker block(material_);
        bool same = material_->count() == static_cast<int>(scene.materials.size());
        for (int i = 0; same && i < material_->count(); ++i)
            same = material_->itemText(i).toStdString() == scene.materials[i].name;
        if (!same) {
            material_->clear();
            for (const Material& m : scene.materials)
                material_->addItem(QString::fromStdString(m.name));
        }
        // Spheres of several materials show none until one is chosen for all.
        bool mixed = false;
        for (int i : targets()) mixed = mixed || scene.spheres[i].material != sphere.material;
        material_->setPlaceholderText(tr("mixed"));
        material_->setCurrentIndex(mixed ? -1 : findMaterial(scene, sphere.material));
    }
    // Counted over every sphere, which at a million was a third of each G
    // move: during a gesture only when it added a sphere (Shift+D, Shift+A) or
    // the page shows another material, since moving, scaling and setting
    // values leave it as it was.
    if (!doc_->inGesture() || sphere.material != countedMaterial_ ||
        scene.spheres.size() != countedAmong_) {
        usersCount_ = spheresUsing(scene, sphere.material);
        countedMaterial_ = sphere.material;
        countedAmong_ = scene.spheres.size();
    }
    const int users = usersCount_;
    users_->setText(material_->currentIndex() < 0
                        ? tr("%1 materials: the rows below set them all").arg(materials_.size())
                    : users > 1 ? tr("Shared by %1 spheres").arg(users)
                                : tr("Used by this sphere only"));
    makeUnique_->setEnabled(users > 1);
}

}  // namespace whitted::ui
