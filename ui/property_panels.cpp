// The property, camera and render settings panels: forms of bound fields.
#include "property_panels.h"

#include <limits>

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QStackedWidget>
#include <QVBoxLayout>

#include "color_button.h"
#include "image_size_fields.h"
#include "number_field.h"
#include "preset_controls.h"

namespace whitted::ui {

namespace {

// Positions, directions and lengths: every finite value the file format allows
// (scenes/extremes/ holds floors of radius 1e9 and balls of radius 5e-5), so a
// value from a file is never clamped on display or on the next edit.
constexpr double kLargest = std::numeric_limits<double>::max();
constexpr double kSmallestLength = std::numeric_limits<double>::denorm_min();
const DoubleFieldSpec kCoordinate = DoubleFieldSpec::range(-kLargest, kLargest, 0.1);
const DoubleFieldSpec kLength =
    DoubleFieldSpec::range(kSmallestLength, kLargest, 0.1).adaptive().logSlider(0.01, 100.0);
const DoubleFieldSpec kUnitInterval = DoubleFieldSpec::range(0.0, 1.0, 0.05).linearSlider(0.0, 1.0);

// Item `i` of a list, const or not like the list, or nullptr when it is gone.
template <class List>
auto itemAt(List& list, int i) -> decltype(&list[0]) {
    return i >= 0 && i < static_cast<int>(list.size()) ? &list[i] : nullptr;
}

// A field for the double that `access(scene)` points to (nullptr: item gone).
// `access` is generic so that one lambda serves the const getter and the setter.
template <class Access>
DoubleField* makeField(SceneDocument* doc, const QString& name, const DoubleFieldSpec& spec,
                       Access access, DoubleField::TextFn text, std::vector<DoubleField*>& fields) {
    auto* field = new DoubleField(
        doc, name, spec,
        [access](const Scene& s) {
            const double* v = access(s);
            return v ? *v : 0.0;
        },
        [access](Scene& s, double value) {
            if (double* v = access(s)) *v = value;
        },
        std::move(text));
    fields.push_back(field);
    return field;
}

// Three fields in a row, named <name>X, <name>Y, <name>Z, for the Vec3 `access` points to.
template <class Access>
QWidget* makeVectorRow(SceneDocument* doc, const QString& name, const DoubleFieldSpec& spec,
                       Access access, const DoubleField::TextFn& text,
                       std::vector<DoubleField*>& fields) {
    auto* row = new QWidget;
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(4);
    static const char* const kAxes[] = {"X", "Y", "Z"};
    for (int axis = 0; axis < 3; ++axis) {
        auto component = [access, axis](auto& s) {
            auto* v = access(s);
            return v ? &(*v)[axis] : nullptr;
        };
        DoubleField* field =
            makeField(doc, name + QLatin1String(kAxes[axis]), spec, component, text, fields);
        field->spinBox()->setToolTip(QString(QLatin1Char('x' + axis)));
        layout->addWidget(field);
    }
    return row;
}

QFormLayout* makeForm(QWidget* page) {
    auto* form = new QFormLayout(page);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    form->setLabelAlignment(Qt::AlignRight | Qt::AlignVCenter);
    form->setRowWrapPolicy(QFormLayout::DontWrapRows);
    return form;
}

QLabel* makeNameLabel(const QString& objectName) {
    auto* label = new QLabel;
    label->setObjectName(objectName);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    QFont font = label->font();
    font.setBold(true);
    label->setFont(font);
    return label;
}

void refreshAll(const std::vector<DoubleField*>& fields) {
    for (DoubleField* field : fields) field->refresh();
}

}  // namespace

// ---------------------------------------------------------------------------
// PropertyPanel

PropertyPanel::PropertyPanel(SceneDocument* doc, QWidget* parent)
    : QWidget(parent), doc_(doc), pages_(new QStackedWidget(this)) {
    pages_->setObjectName(QStringLiteral("propertyPages"));
    auto* empty = new QLabel(tr("Select a sphere, light or material to edit it."));
    empty->setObjectName(QStringLiteral("emptyPage"));
    empty->setAlignment(Qt::AlignCenter);
    empty->setWordWrap(true);
    empty->setEnabled(false);  // greyed: a hint, not content
    emptyPage_ = empty;
    spherePage_ = buildSpherePage();
    lightPage_ = buildLightPage();
    materialPage_ = buildMaterialPage();
    for (QWidget* page : {emptyPage_, spherePage_, lightPage_, materialPage_})
        pages_->addWidget(page);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(pages_);
    connect(doc_, &SceneDocument::sceneChanged, this, &PropertyPanel::refresh);
    refresh();
}

void PropertyPanel::showItem(ItemKind kind, int index) {
    kind_ = kind;
    index_ = index;
    refresh();
}

bool PropertyPanel::valid() const {
    return index_ >= 0 && index_ < itemCount(doc_->scene(), kind_);
}

QString PropertyPanel::itemLabel() const {
    return itemName(doc_->scene(), kind_, index_);
}

std::function<QString()> PropertyPanel::changeText(const QString& what) const {
    return [this, what] { return tr("Change %1 of %2").arg(what, itemLabel()); };
}

void PropertyPanel::editItem(const QString& what, const std::function<void(Scene&)>& change) {
    QString error;
    if (!doc_->edit(changeText(what)(), change, &error)) {
        showRefusal(this, error);
        refresh();
    }
}

QWidget* PropertyPanel::buildSpherePage() {
    auto* page = new QWidget;
    page->setObjectName(QStringLiteral("spherePage"));
    QFormLayout* form = makeForm(page);
    auto sphere = [this](auto& s) { return itemAt(s.spheres, index_); };

    sphereName_ = makeNameLabel(QStringLiteral("sphereName"));
    form->addRow(tr("Sphere:"), sphereName_);
    form->addRow(tr("Centre:"), makeVectorRow(
                                    doc_, QStringLiteral("sphereCenter"), kCoordinate,
                                    [sphere](auto& s) {
                                        auto* sp = sphere(s);
                                        return sp ? &sp->center : nullptr;
                                    },
                                    changeText(tr("centre")), sphereFields_));
    form->addRow(tr("Radius:"), makeField(
                                    doc_, QStringLiteral("sphereRadius"), kLength,
                                    [sphere](auto& s) {
                                        auto* sp = sphere(s);
                                        return sp ? &sp->radius : nullptr;
                                    },
                                    changeText(tr("radius")), sphereFields_));

    sphereMaterial_ = new QComboBox;
    sphereMaterial_->setObjectName(QStringLiteral("sphereMaterial"));
    sphereMaterial_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    sphereMaterial_->setMinimumContentsLength(12);
    connect(sphereMaterial_, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (i < 0 || i >= static_cast<int>(doc_->scene().materials.size())) return;
        const std::string material = doc_->scene().materials[i].name;
        editItem(tr("material"), [this, material](Scene& s) {
            if (Sphere* sp = itemAt(s.spheres, index_)) sp->material = material;
        });
    });
    form->addRow(tr("Material:"), sphereMaterial_);
    return page;
}

QWidget* PropertyPanel::buildLightPage() {
    auto* page = new QWidget;
    page->setObjectName(QStringLiteral("lightPage"));
    QFormLayout* form = makeForm(page);
    auto light = [this](auto& s) { return itemAt(s.lights, index_); };

    lightName_ = makeNameLabel(QStringLiteral("lightName"));
    form->addRow(tr("Light:"), lightName_);
    form->addRow(tr("Position:"), makeVectorRow(
                                      doc_, QStringLiteral("lightPosition"), kCoordinate,
                                      [light](auto& s) {
                                          auto* l = light(s);
                                          return l ? &l->position : nullptr;
                                      },
                                      changeText(tr("position")), lightFields_));

    lightColor_ = new ColorButton;
    lightColor_->setObjectName(QStringLiteral("lightColor"));
    connect(lightColor_, &ColorButton::colorEdited, this, [this](const Vec3& c) {
        editItem(tr("colour"), [this, c](Scene& s) {
            if (Light* l = itemAt(s.lights, index_)) l->color = c;
        });
    });
    form->addRow(tr("Colour:"), lightColor_);
    form->addRow(tr("Intensity:"),
                 makeField(
                     doc_, QStringLiteral("lightIntensity"),
                     DoubleFieldSpec::range(0.0, 1000.0, 0.1).linearSlider(0.0, 10.0),
                     [light](auto& s) {
                         auto* l = light(s);
                         return l ? &l->intensity : nullptr;
                     },
                     changeText(tr("intensity")), lightFields_));
    return page;
}

QWidget* PropertyPanel::buildMaterialPage() {
    auto* page = new QWidget;
    page->setObjectName(QStringLiteral("materialPage"));
    QFormLayout* form = makeForm(page);
    auto material = [this](auto& s) { return itemAt(s.materials, index_); };
    // A field for one double member of the material.
    auto scalar = [&](const QString& name, const DoubleFieldSpec& spec, auto member,
                      const QString& what) {
        return makeField(
            doc_, name, spec,
            [material, member](auto& s) {
                auto* m = material(s);
                return m ? &(m->*member) : nullptr;
            },
            changeText(what), materialFields_);
    };

    materialName_ = makeNameLabel(QStringLiteral("materialName"));
    form->addRow(tr("Material:"), materialName_);

    materialDiffuse_ = new ColorButton;
    materialDiffuse_->setObjectName(QStringLiteral("materialDiffuse"));
    connect(materialDiffuse_, &ColorButton::colorEdited, this, [this](const Vec3& c) {
        editItem(tr("diffuse colour"), [this, c](Scene& s) {
            if (Material* m = itemAt(s.materials, index_)) m->diffuse = c;
        });
    });
    form->addRow(tr("Diffuse:"), materialDiffuse_);
    form->addRow(tr("Specular:"),
                 scalar(QStringLiteral("materialSpecular"),
                        DoubleFieldSpec::range(0.0, 10.0, 0.05).linearSlider(0.0, 2.0),
                        &Material::specular, tr("specular")));
    form->addRow(tr("Shininess:"),
                 scalar(QStringLiteral("materialShininess"),
                        DoubleFieldSpec::range(0.0, 10000.0, 1.0).logSlider(1.0, 10000.0),
                        &Material::shininess, tr("shininess")));
    form->addRow(tr("Reflectivity:"), scalar(QStringLiteral("materialReflectivity"), kUnitInterval,
                                             &Material::reflectivity, tr("reflectivity")));
    form->addRow(tr("Transparency:"), scalar(QStringLiteral("materialTransparency"), kUnitInterval,
                                             &Material::transparency, tr("transparency")));
    form->addRow(tr("Index of refraction:"),
                 scalar(QStringLiteral("materialIor"),
                        DoubleFieldSpec::range(0.01, 100.0, 0.01).linearSlider(1.0, 3.0),
                        &Material::ior, tr("index of refraction")));

    materialChecker_ = new QCheckBox(tr("Checker pattern"));
    materialChecker_->setObjectName(QStringLiteral("materialChecker"));
    checkerColor_ = new ColorButton;
    checkerColor_->setObjectName(QStringLiteral("materialCheckerColor"));
    checkerColor_->setColor(Checker{}.color);
    // The size field keeps showing its last value while the checker is off, so
    // turning it back on restores what the user had.
    checkerSize_ = makeField(
        doc_, QStringLiteral("materialCheckerSize"),
        DoubleFieldSpec::range(kSmallestLength, kLargest, 0.1).adaptive(),
        [this, material](auto& s) {
            auto* m = material(s);
            return m && m->checker ? &m->checker->size : nullptr;
        },
        changeText(tr("checker size")), materialFields_);
    materialFields_.pop_back();  // refreshed only while a checker exists
    {
        const QSignalBlocker block(checkerSize_->spinBox());
        checkerSize_->spinBox()->setValue(Checker{}.size);
    }

    connect(materialChecker_, &QCheckBox::toggled, this, [this](bool on) {
        std::optional<Checker> checker;
        if (on) checker = Checker{checkerColor_->color(), checkerSize_->spinBox()->value()};
        editItem(tr("checker"), [this, checker](Scene& s) {
            if (Material* m = itemAt(s.materials, index_)) m->checker = checker;
        });
    });
    connect(checkerColor_, &ColorButton::colorEdited, this, [this](const Vec3& c) {
        editItem(tr("checker colour"), [this, c](Scene& s) {
            Material* m = itemAt(s.materials, index_);
            if (m && m->checker) m->checker->color = c;
        });
    });
    form->addRow(QString(), materialChecker_);
    form->addRow(tr("Checker colour:"), checkerColor_);
    form->addRow(tr("Checker size:"), checkerSize_);
    return page;
}

void PropertyPanel::refresh() {
    if (!valid()) {
        pages_->setCurrentWidget(emptyPage_);
        return;
    }
    const Scene& scene = doc_->scene();
    switch (kind_) {
        case ItemKind::Sphere: {
            const Sphere& sphere = scene.spheres[index_];
            sphereName_->setText(QString::fromStdString(sphere.name));
            refreshAll(sphereFields_);
            const QSignalBlocker block(sphereMaterial_);
            bool same = sphereMaterial_->count() == static_cast<int>(scene.materials.size());
            for (int i = 0; same && i < sphereMaterial_->count(); ++i)
                same = sphereMaterial_->itemText(i).toStdString() == scene.materials[i].name;
            if (!same) {
                sphereMaterial_->clear();
                for (const Material& m : scene.materials)
                    sphereMaterial_->addItem(QString::fromStdString(m.name));
            }
            sphereMaterial_->setCurrentIndex(findMaterial(scene, sphere.material));
            pages_->setCurrentWidget(spherePage_);
            break;
        }
        case ItemKind::Light: {
            const Light& light = scene.lights[index_];
            lightName_->setText(QString::fromStdString(light.name));
            refreshAll(lightFields_);
            lightColor_->setColor(light.color);
            pages_->setCurrentWidget(lightPage_);
            break;
        }
        case ItemKind::Material: {
            const Material& material = scene.materials[index_];
            materialName_->setText(QString::fromStdString(material.name));
            refreshAll(materialFields_);
            materialDiffuse_->setColor(material.diffuse);
            {
                const QSignalBlocker block(materialChecker_);
                materialChecker_->setChecked(material.checker.has_value());
            }
            if (material.checker) {
                checkerColor_->setColor(material.checker->color);
                checkerSize_->refresh();
            }
            checkerColor_->setEnabled(material.checker.has_value());
            checkerSize_->setEnabled(material.checker.has_value());
            pages_->setCurrentWidget(materialPage_);
            break;
        }
    }
}

// ---------------------------------------------------------------------------
// CameraPanel

CameraPanel::CameraPanel(SceneDocument* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
    QFormLayout* form = makeForm(this);
    auto text = [](const QString& what) {
        return [what] { return tr("Change camera %1").arg(what); };
    };
    form->addRow(tr("Position:"),
                 makeVectorRow(
                     doc_, QStringLiteral("cameraPosition"), kCoordinate,
                     [](auto& s) { return &s.camera.position; }, text(tr("position")), fields_));
    form->addRow(tr("Look at:"),
                 makeVectorRow(
                     doc_, QStringLiteral("cameraLookAt"), kCoordinate,
                     [](auto& s) { return &s.camera.lookAt; }, text(tr("look-at point")), fields_));
    form->addRow(tr("Up:"),
                 makeVectorRow(
                     doc_, QStringLiteral("cameraUp"), kCoordinate,
                     [](auto& s) { return &s.camera.up; }, text(tr("up vector")), fields_));
    form->addRow(tr("Vertical FOV:"), makeField(
                                          doc_, QStringLiteral("cameraVfov"),
                                          DoubleFieldSpec::range(0.01, 179.99, 1.0)
                                              .linearSlider(1.0, 170.0)
                                              .unit(QStringLiteral(" °")),
                                          [](auto& s) { return &s.camera.vfovDegrees; },
                                          text(tr("field of view")), fields_));
    connect(doc_, &SceneDocument::sceneChanged, this, &CameraPanel::refresh);
    refresh();
}

void CameraPanel::refresh() {
    refreshAll(fields_);
}

// ---------------------------------------------------------------------------
// RenderSettingsPanel

RenderSettingsPanel::RenderSettingsPanel(SceneDocument* doc, TradeoffRecord* record,
                                         QWidget* parent)
    : QWidget(parent), doc_(doc) {
    QFormLayout* form = makeForm(this);
    auto addInt = [&](const QString& label, const QString& name, int min, int max, auto member,
                      const QString& what, const QString& suffix) {
        auto* field = new IntField(
            doc_, name, min, max, [member](const Scene& s) { return s.render.*member; },
            [member](Scene& s, int v) { s.render.*member = v; },
            [what] { return tr("Change %1").arg(what); });
        field->setSuffix(suffix);
        fields_.push_back(field);
        form->addRow(label, field);
    };
    addInt(tr("Width:"), QStringLiteral("renderWidth"), 1, kMaxImageSize, &RenderSettings::width,
           tr("image width"), tr(" px"));
    addInt(tr("Height:"), QStringLiteral("renderHeight"), 1, kMaxImageSize, &RenderSettings::height,
           tr("image height"), tr(" px"));
    form->addRow(tr("Common size:"), makeCommonSizeChooser(doc_));
    addInt(tr("Max depth:"), QStringLiteral("renderMaxDepth"), 0, kMaxDepth,
           &RenderSettings::maxDepth, tr("maximum depth"), QString());
    addInt(tr("Samples per pixel:"), QStringLiteral("renderSamples"), 1, kMaxSamplesPerPixel,
           &RenderSettings::samplesPerPixel, tr("samples per pixel"), QString());

    precision_ = new QComboBox;
    precision_->setObjectName(QStringLiteral("renderPrecision"));
    for (const auto& [precision, name] : kPrecisionNames)
        precision_->addItem(QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size())),
                            static_cast<int>(precision));
    connect(precision_, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (i < 0) return;
        const auto precision = static_cast<Precision>(precision_->itemData(i).toInt());
        QString error;
        if (!doc_->edit(
                tr("Change precision"), [precision](Scene& s) { s.render.precision = precision; },
                &error)) {
            showRefusal(this, error);
            refresh();
        }
    });
    form->addRow(tr("Precision:"), precision_);

    auto addColor = [&](const QString& label, const QString& name, Vec3 Scene::*member,
                        const QString& what) {
        auto* button = new ColorButton;
        button->setObjectName(name);
        connect(button, &ColorButton::colorEdited, this, [this, member, what](const Vec3& c) {
            QString error;
            if (!doc_->edit(
                    tr("Change %1").arg(what), [&](Scene& s) { s.*member = c; }, &error)) {
                showRefusal(this, error);
                refresh();
            }
        });
        form->addRow(label, button);
        return button;
    };
    background_ = addColor(tr("Background:"), QStringLiteral("sceneBackground"), &Scene::background,
                           tr("background colour"));
    ambient_ = addColor(tr("Ambient:"), QStringLiteral("sceneAmbient"), &Scene::ambient,
                        tr("ambient colour"));

    if (record) new PresetControls(doc_, record, form);

    connect(doc_, &SceneDocument::sceneChanged, this, &RenderSettingsPanel::refresh);
    refresh();
}

void RenderSettingsPanel::refresh() {
    for (IntField* field : fields_) field->refresh();
    const Scene& scene = doc_->scene();
    {
        const QSignalBlocker block(precision_);
        precision_->setCurrentIndex(precision_->findData(static_cast<int>(scene.render.precision)));
    }
    background_->setColor(scene.background);
    ambient_->setColor(scene.ambient);
}

}  // namespace whitted::ui
