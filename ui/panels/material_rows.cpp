#include "panels/material_rows.h"

#include <QFormLayout>

#include "panels/color_button.h"
#include "panels/panel_fields.h"

namespace whitted::ui {

MaterialRows::MaterialRows(SceneDocument* doc, QWidget* owner, QFormLayout* form, Extent extent,
                           const QString& prefix, Targets targets, TextFn text)
    : doc_(doc), targets_(std::move(targets)), text_(std::move(text)), diffuse_(new ColorButton) {
    diffuse_->setObjectName(prefix + QStringLiteral("Diffuse"));
    QObject::connect(diffuse_, &ColorButton::colorEdited, owner, [this, owner](const Vec3& c) {
        editItemsOrTell<Material>(owner, doc_, targets_(doc_->scene()),
                                  text_(QObject::tr("diffuse colour")),
                                  [c](Material& m) { m.diffuse = c; });
    });
    const bool all = extent == Extent::All;
    // On a sphere's page "Colour" is what the user looks for; the material page
    // names the shading term.
    form->addRow(all ? QObject::tr("Diffuse:") : QObject::tr("Colour:"), diffuse_);
    if (all) {
        form->addRow(QObject::tr("Specular:"),
                     scalar(prefix + QStringLiteral("Specular"),
                            DoubleFieldSpec::range(0.0, 10.0, 0.05).linearSlider(0.0, 2.0),
                            &Material::specular, QObject::tr("specular")));
        form->addRow(QObject::tr("Shininess:"),
                     scalar(prefix + QStringLiteral("Shininess"),
                            DoubleFieldSpec::range(0.0, 10000.0, 1.0).logSlider(1.0, 10000.0),
                            &Material::shininess, QObject::tr("shininess")));
    }
    form->addRow(QObject::tr("Reflectivity:"),
                 scalar(prefix + QStringLiteral("Reflectivity"), kUnitInterval,
                        &Material::reflectivity, QObject::tr("reflectivity")));
    form->addRow(QObject::tr("Transparency:"),
                 scalar(prefix + QStringLiteral("Transparency"), kUnitInterval,
                        &Material::transparency, QObject::tr("transparency")));
    form->addRow(QObject::tr("Index of refraction:"),
                 scalar(prefix + QStringLiteral("Ior"),
                        DoubleFieldSpec::range(0.01, 100.0, 0.01).linearSlider(1.0, 3.0),
                        &Material::ior, QObject::tr("index of refraction")));
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
