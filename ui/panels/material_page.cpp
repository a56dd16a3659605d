#include "panels/material_page.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QSignalBlocker>

#include "document/field_words.h"
#include "panels/color_button.h"
#include "panels/material_rows.h"
#include "panels/panel_fields.h"
#include "scene/material_presets.h"

namespace whitted::ui {

MaterialPage::MaterialPage(SceneDocument* doc, QWidget* parent)
    : QWidget(parent), doc_(doc), name_(makeNameLabel(QStringLiteral("materialName"))) {
    setObjectName(QStringLiteral("materialPage"));
    QFormLayout* form = makeForm(this);
    form->addRow(tr("Material:"), name_);
    form->addRow(tr("Preset:"), buildPresetChooser());
    rows_ = std::make_unique<MaterialRows>(
        doc_, this, form, MaterialRows::Extent::All, QStringLiteral("material"),
        [this](const Scene&) { return targets(); },
        [this](const QString& what) { return changeText(what)(); });
    addCheckerRows(form);
}

MaterialPage::~MaterialPage() = default;

std::vector<int> MaterialPage::targets() const {
    return editTargets(*doc_, ItemKind::Material, index_);
}

QString MaterialPage::materialName() const {
    const int others = int(targets().size()) - 1;
    const QString name = itemName(doc_->scene(), ItemKind::Material, index_);
    return others == 0 ? name : tr("%1 (and %2 more)").arg(name).arg(others);
}

std::function<QString()> MaterialPage::changeText(const QString& what) const {
    return [this, what] { return tr("Change %1 of %2").arg(what, materialName()); };
}

void MaterialPage::editMaterial(const QString& what, const std::function<void(Material&)>& change) {
    if (!editItemsOrTell(this, doc_, targets(), changeText(what)(), change)) refresh();
}

// Shows the preset the material's finish is, or "Custom"; choosing one
// applies it (the name and checker stay) as one undo step.
QComboBox* MaterialPage::buildPresetChooser() {
    preset_ = new QComboBox;
    preset_->setObjectName(QStringLiteral("materialPreset"));
    preset_->setToolTip(tr("Set the finish to a typical material; the name and checker stay"));
    preset_->addItem(tr("Custom"), -1);
    const auto presets = materialPresets();
    for (std::size_t i = 0; i < presets.size(); ++i)
        preset_->addItem(QString::fromUtf8(presets[i].name.data(),
                                           static_cast<qsizetype>(presets[i].name.size())),
                         static_cast<int>(i));
    connect(preset_, &QComboBox::activated, this, [this](int row) {
        const int preset = preset_->itemData(row).toInt();
        if (preset < 0) return refresh();
        const MaterialPreset& p = materialPresets()[static_cast<std::size_t>(preset)];
        if (!editItemsOrTell<Material>(
                this, doc_, targets(),
                tr("Apply preset %1 to %2").arg(preset_->itemText(row), materialName()),
                [&p](Material& m) { m = withPreset(m, p); }))
            refresh();
    });
    return preset_;
}

void MaterialPage::addCheckerRows(QFormLayout* form) {
    checker_ = new QCheckBox(tr("Checker pattern"));
    checker_->setObjectName(QStringLiteral("materialChecker"));
    checkerColor_ = new ColorButton;
    checkerColor_->setObjectName(QStringLiteral("materialCheckerColor"));
    checkerColor_->setColor(Checker{}.color);
    // The size field keeps showing its last value while the checker is off, so
    // turning it back on restores what the user had.
    std::vector<DoubleField*> unused;
    checkerSize_ = makeItemsField<Material>(
        doc_, QStringLiteral("materialCheckerSize"), kPositiveLength,
        [this](const Scene&) { return targets(); },
        [](auto& m) { return m.checker ? &m.checker->size : nullptr; },
        changeText(fieldChanged(scene_field::kCheckerSize)), unused);
    {
        const QSignalBlocker block(checkerSize_->spinBox());
        checkerSize_->spinBox()->setValue(Checker{}.size);
    }
    connect(checker_, &QCheckBox::toggled, this, [this](bool on) {
        std::optional<Checker> checker;
        if (on) checker = Checker{checkerColor_->color(), checkerSize_->spinBox()->value()};
        editMaterial(fieldChanged(scene_field::kChecker),
                     [checker](Material& m) { m.checker = checker; });
    });
    connect(checkerColor_, &ColorButton::colorEdited, this, [this](const Vec3& c) {
        editMaterial(fieldChanged(scene_field::kCheckerColour), [c](Material& m) {
            if (m.checker) m.checker->color = c;
        });
    });
    form->addRow(QString(), checker_);
    form->addRow(fieldRow(scene_field::kCheckerColour), checkerColor_);
    form->addRow(fieldRow(scene_field::kCheckerSize), checkerSize_);
}

void MaterialPage::setIndex(int index) {
    index_ = index;
    refresh();
}

void MaterialPage::refresh() {
    const Material* material = itemAt(doc_->scene().materials, index_);
    if (!material) return;
    name_->setText(materialName());
    {
        const QSignalBlocker block(preset_);
        int shown = 0;  // Custom
        const auto presets = materialPresets();
        for (std::size_t i = 0; i < presets.size(); ++i)
            if (withPreset(*material, presets[i]) == *material) shown = static_cast<int>(i) + 1;
        preset_->setCurrentIndex(shown);
    }
    rows_->refresh();
    {
        const QSignalBlocker block(checker_);
        checker_->setChecked(material->checker.has_value());
    }
    if (material->checker) {
        checkerColor_->setColor(material->checker->color);
        checkerSize_->refresh();
    }
    checkerColor_->setEnabled(material->checker.has_value());
    checkerSize_->setEnabled(material->checker.has_value());
}

}  // namespace whitted::ui
