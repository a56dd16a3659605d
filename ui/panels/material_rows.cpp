#include "panels/material_rows.h"

#include <QFormLayout>

#include "document/field_words.h"
#include "panels/color_button.h"
#include "panels/panel_fields.h"

namespace whitted::ui {

MaterialRows::MaterialRows(SceneDocument* doc, QWidget* owner, QFormLayout* form, Extent extent,
                           const QString& prefix, Targets targets, TextFn text)
    : doc_(doc), targets_(std::move(targets)), text_(std::move(text)), diffuse_(new ColorButton) {
    diffuse_->setObjectName(prefix + QStringLiteral("Diffuse"));
    QObject::connect(diffuse_, &ColorButton::colorEdited, owner, [this, owner](const Vec3& c) {
        editItemsOrTell<Material>(owner, doc_, targets_(doc_->scene()),
                                  text_(fieldChanged(scene_field::kDiffuse)),
                                  [c](Material& m) { m.diffuse = c; });
    });
    const bool all = extent == Extent::All;
    // On a sphere's page "Colour" is what the user looks for; the material page
    // names the shading term.
    form->addRow(all ? fieldRow(scene_field::kDiffuse) : QObject::tr("Colour:"), diffuse_);
    if (all) {
        form->addRow(fieldRow(scene_field::kSpecular),
                     scalar(prefix + QStringLiteral("Specular"),
                            DoubleFieldSpec::range(0.0, 10.0, 0.05).linearSlider(0.0, 2.0),
                            &Material::specular, fieldChanged(scene_field::kSpecular)));
        form->addRow(fieldRow(scene_field::kShininess),
                     scalar(prefix + QStringLiteral("Shininess"),
                            DoubleFieldSpec::range(0.0, 10000.0, 1.0).logSlider(1.0, 10000.0),
                            &Material::shininess, fieldChanged(scene_field::kShininess)));
    }
    form->addRow(fieldRow(scene_field::kReflectivity),
                 scalar(prefix + QStringLiteral("Reflectivity"), kUnitInterval,
                        &Material::reflectivity, fieldChanged(scene_field::kReflectivity)));
    form->addRow(fieldRow(scene_field::kTransparency),
                 scalar(prefix + QStringLiteral("Transparency"), kUnitInterval,
                        &Material::transparency, fieldChanged(scene_field::kTransparency)));
    form->addRow(fieldRow(scene_field::kIor),
                 scalar(prefix + QStringLiteral("Ior"),
                        DoubleFieldSpec::range(0.01, 100.0, 0.01).linearSlider(1.0, 3.0),
                        &Material::ior, fieldChanged(scene_field::kIor)));
}

DoubleField* MaterialRows::scalar(const QString& name, const DoubleFieldSpec& spec,
                                  double Material::*member, const QString& what) {
    return makeItemsField<Material>(
        doc_, name, spec, targets_, [member](auto& m) { return &(m.*member); },
        [this, what] { return text_(what); }, fields_);
}

void MaterialRows::refresh() {
    const Scene& scene = doc_->scene();
    const std::vector<int> targets = targets_(scene);
    const Material* m = targets.empty() ? nullptr : itemAt(scene.materials, targets.front());
    if (!m) return;
    diffuse_->setColor(m->diffuse);
    refreshAll(fields_);
}

}  // namespace whitted::ui
