// The property, camera and render settings panels: forms of bound fields.
#include "panels/property_panels.h"

#include <string_view>

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QStackedWidget>
#include <QVBoxLayout>

#include "document/field_words.h"
#include "document/quality_choice.h"
#include "panels/color_button.h"
#include "panels/image_size_fields.h"
#include "panels/material_page.h"
#include "panels/number_field.h"
#include "panels/panel_fields.h"
#include "panels/preset_controls.h"
#include "panels/sampler_controls.h"
#include "panels/sphere_page.h"

namespace whitted::ui {

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
    spherePage_ = new SpherePage(doc_);
    lightPage_ = buildLightPage();
    materialPage_ = new MaterialPage(doc_);
    for (QWidget* page :
         std::initializer_list<QWidget*>{emptyPage_, spherePage_, lightPage_, materialPage_})
        pages_->addWidget(page);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(pages_);
    connect(doc_, &SceneDocument::sceneChanged, this, &PropertyPanel::refresh);
    connect(doc_->selection(), &SceneSelection::changed, this, &PropertyPanel::refresh);
    refresh();
}

bool PropertyPanel::valid() const {
    return index() >= 0 && index() < itemCount(doc_->scene(), kind());
}

QString PropertyPanel::itemLabel() const {
    const int others = int(editTargets(*doc_, kind(), index()).size()) - 1;
    const QString name = itemName(doc_->scene(), kind(), index());
    return others == 0 ? name : tr("%1 (and %2 more)").arg(name).arg(others);
}

std::function<QString()> PropertyPanel::changeText(const QString& what) const {
    return [this, what] { return tr("Change %1 of %2").arg(what, itemLabel()); };
}

void PropertyPanel::editLight(const QString& what, const std::function<void(Light&)>& change) {
    if (!editItemsOrTell<Light>(this, doc_, editTargets(*doc_, ItemKind::Light, index()),
                                changeText(what)(), change))
        refresh();
}

QWidget* PropertyPanel::buildLightPage() {
    auto* page = new QWidget;
    page->setObjectName(QStringLiteral("lightPage"));
    QFormLayout* form = makeForm(page);
    const Targets targets = [this](const Scene&) {
        return editTargets(*doc_, ItemKind::Light, index());
    };

    lightName_ = makeNameLabel(QStringLiteral("lightName"));
    form->addRow(tr("Light:"), lightName_);
    form->addRow(fieldRow(scene_field::kLightPosition),
                 makeItemsVectorRow<Light>(
                     doc_, QStringLiteral("lightPosition"), kCoordinate, targets,
                     [](auto& l) { return &l.position; },
                     changeText(fieldChanged(scene_field::kLightPosition)), lightFields_));

    lightColor_ = new ColorButton;
    lightColor_->setObjectName(QStringLiteral("lightColor"));
    connect(lightColor_, &ColorButton::colorEdited, this, [this](const Vec3& c) {
        editLight(fieldChanged(scene_field::kLightColour), [c](Light& l) { l.color = c; });
    });
    form->addRow(fieldRow(scene_field::kLightColour), lightColor_);
    form->addRow(fieldRow(scene_field::kIntensity),
                 makeItemsField<Light>(
                     doc_, QStringLiteral("lightIntensity"),
                     DoubleFieldSpec::range(0.0, 1000.0, 0.1).linearSlider(0.0, 10.0), targets,
                     [](auto& l) { return &l.intensity; },
                     changeText(fieldChanged(scene_field::kIntensity)), lightFields_));
    return page;
}

void PropertyPanel::refresh() {
    if (!valid()) {
        pages_->setCurrentWidget(emptyPage_);
        return;
    }
    const Scene& scene = doc_->scene();
    switch (kind()) {
        case ItemKind::Sphere:
            spherePage_->setIndex(index());
            pages_->setCurrentWidget(spherePage_);
            break;
        case ItemKind::Light: {
            const Light& light = scene.lights[index()];
            lightName_->setText(itemLabel());
            refreshAll(lightFields_);
            lightColor_->setColor(light.color);
            pages_->setCurrentWidget(lightPage_);
            break;
        }
        case ItemKind::Material:
            materialPage_->setIndex(index());
            pages_->setCurrentWidget(materialPage_);
            break;
    }
}

// ---------------------------------------------------------------------------
// CameraPanel

CameraPanel::CameraPanel(SceneDocument* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
    QFormLayout* form = makeForm(this);
    auto text = [](const SceneField& field) {
        return [what = fieldChanged(field)] { return tr("Change %1").arg(what); };
    };
    form->addRow(fieldRow(scene_field::kCameraPosition),
                 makeVectorRow(
                     doc_, QStringLiteral("cameraPosition"), kCoordinate,
                     [](auto& s) { return &s.camera.position; }, text(scene_field::kCameraPosition),
                     fields_));
    form->addRow(
        fieldRow(scene_field::kLookAt),
        makeVectorRow(
            doc_, QStringLiteral("cameraLookAt"), kCoordinate,
            [](auto& s) { return &s.camera.lookAt; }, text(scene_field::kLookAt), fields_));
    form->addRow(fieldRow(scene_field::kUp),
                 makeVectorRow(
                     doc_, QStringLiteral("cameraUp"), kCoordinate,
                     [](auto& s) { return &s.camera.up; }, text(scene_field::kUp), fields_));
    form->addRow(fieldRow(scene_field::kFieldOfView),
                 makeField(
                     doc_, QStringLiteral("cameraVfov"),
                     DoubleFieldSpec::range(0.01, 179.99, 1.0)
                         .linearSlider(1.0, 170.0)
                         .unit(QStringLiteral(" °")),
                     [](auto& s) { return &s.camera.vfovDegrees; }, text(scene_field::kFieldOfView),
                     fields_));
    connect(doc_, &SceneDocument::sceneChanged, this, &CameraPanel::refresh);
    refresh();
}

void CameraPanel::refresh() {
    refreshAll(fields_);
}

// ---------------------------------------------------------------------------
// RenderSettingsPanel

RenderSettingsPanel::RenderSettingsPanel(SceneDocument* doc, RenderRecord* record,
                                         QualityChoice* quality, QWidget* parent)
    : QWidget(parent), doc_(doc) {
    QFormLayout* form = makeForm(this);
    addIntRows(form);
    addPrecisionRow(form);
    background_ = addColourRow(form, scene_field::kBackground, QStringLiteral("sceneBackground"),
                               &Scene::background);
    ambient_ =
        addColourRow(form, scene_field::kAmbient, QStringLiteral("sceneAmbient"), &Scene::ambient);
    if (record && quality) {
        new PresetControls(doc_, record, quality, form);
        connect(quality, &QualityChoice::changed, this, [this, quality] { followTarget(quality); });
        followTarget(quality);
        addSamplerRows(form, quality);
    }
    connect(doc_, &SceneDocument::sceneChanged, this, &RenderSettingsPanel::refresh);
    refresh();
}

void RenderSettingsPanel::addIntRows(QFormLayout* form) {
    auto addInt = [&](const SceneField& setting, const QString& name, int min, int max, auto member,
                      const QString& suffix) {
        auto* field = new IntField(
            doc_, name, min, max, [member](const Scene& s) { return s.render.*member; },
            [member](Scene& s, int v) { s.render.*member = v; },
            [what = fieldChanged(setting)] { return tr("Change %1").arg(what); });
        field->setSuffix(suffix);
        fields_.push_back(field);
        form->addRow(fieldRow(setting), field);
    };
    addInt(scene_field::kWidth, QStringLiteral("renderWidth"), 1, kMaxImageSize,
           &RenderSettings::width, tr(" px"));
    addInt(scene_field::kHeight, QStringLiteral("renderHeight"), 1, kMaxImageSize,
           &RenderSettings::height, tr(" px"));
    form->addRow(tr("Common size:"), makeCommonSizeChooser(doc_));
    addInt(scene_field::kDepth, QStringLiteral("renderMaxDepth"), 0, kMaxDepth,
           &RenderSettings::maxDepth, QString());
    addInt(scene_field::kSamples, QStringLiteral("renderSamples"), 1, kMaxSamplesPerPixel,
           &RenderSettings::samplesPerPixel, QString());
}

void RenderSettingsPanel::addPrecisionRow(QFormLayout* form) {
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
                tr("Change %1").arg(fieldChanged(scene_field::kPrecision)),
                [precision](Scene& s) { s.render.precision = precision; }, &error)) {
            showRefusal(this, error);
            refresh();
        }
    });
    form->addRow(fieldRow(scene_field::kPrecision), precision_);
}

ColorButton* RenderSettingsPanel::addColourRow(QFormLayout* form, const SceneField& field,
                                               const QString& name, Vec3 Scene::*member) {
    auto* button = new ColorButton;
    button->setObjectName(name);
    const QString what = fieldChanged(field);
    connect(button, &ColorButton::colorEdited, this, [this, member, what](const Vec3& c) {
        QString error;
        if (!doc_->edit(
                tr("Change %1").arg(what), [&](Scene& s) { s.*member = c; }, &error)) {
            showRefusal(this, error);
            refresh();
        }
    });
    form->addRow(fieldRow(field), button);
    return button;
}

// A target chooses depth and samples at each render: the fields would change
// nothing the user sees, so they rest until the settings rule again, and say
// so beside their numbers, which are the settings' and not what the render
// uses (greyed "8" under Final, rendered at 6, read as the depth of the
// picture).
void RenderSettingsPanel::followTarget(const QualityChoice* quality) {
    const QString target =
        quality->target() ? QString::fromStdString(quality->target()->name) : QString();
    for (const char* name : {"renderMaxDepth", "renderSamples"}) {
        const bool samples = std::string_view(name) == "renderSamples";
        QString unused;
        if (!target.isEmpty())
            unused = tr("  (not used while rendering to %1)").arg(target);
        else if (samples && quality->whitted1980())
            unused = tr("  (not used by Whitted 1980 sampling)");
        const bool settings = unused.isEmpty();
        auto* field = findChild<IntField*>(QLatin1String(name));
        field->setSuffix(unused);
        if (field->isEnabled() == settings) continue;
        field->setEnabled(settings);
        // The field's own tooltip comes back with the settings.
        if (!settings) field->setProperty("settingsToolTip", field->toolTip());
        field->setToolTip(settings            ? field->property("settingsToolTip").toString()
                          : !target.isEmpty() ? tr("Chosen for the scene at each render while "
                                                   "rendering to a quality (Render to)")
                                              : tr("Whitted 1980 sampling chooses its own rays "
                                                   "(Antialiasing)"));
    }
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
