#include "document/edit_messages.h"

#include <QObject>
#include <QRegularExpression>

#include "document/scene_document.h"  // ItemKind, kindNoun
#include "scene/scene_io.h"

namespace whitted::ui {

namespace {

// What a field must be, as the end of a sentence.
enum class Rule { Positive, NonNegative, UnitInterval, Finite, Colour, Image, Depth, Samples, Fov };

struct FieldWords {
    const char* path;   // the JSON path after the item ("radius", "checker.size")
    const char* label;  // the form row's label
    Rule rule;
};

// Every field validateScene checks, by list, labelled as the property panels label them.
const FieldWords kSphereFields[] = {
    {"center", "Centre", Rule::Finite},
    {"radius", "Radius", Rule::Positive},
};
const FieldWords kLightFields[] = {
    {"position", "Position", Rule::Finite},
    {"color", "Colour", Rule::Colour},
    {"intensity", "Intensity", Rule::NonNegative},
};
const FieldWords kMaterialFields[] = {
    {"diffuse", "Diffuse colour", Rule::Colour},
    {"specular", "Specular", Rule::NonNegative},
    {"shininess", "Shininess", Rule::NonNegative},
    {"reflectivity", "Reflectivity", Rule::UnitInterval},
    {"transparency", "Transparency", Rule::UnitInterval},
    {"ior", "Index of refraction", Rule::Positive},
    {"checker.color", "Checker colour", Rule::Colour},
    {"checker.size", "Checker size", Rule::Positive},
};
const FieldWords kSceneFields[] = {
    {"camera.position", "Camera position", Rule::Finite},
    {"camera.look_at", "Camera look-at point", Rule::Finite},
    {"camera.up", "Camera up vector", Rule::Finite},
    {"camera.vfov_degrees", "Vertical field of view", Rule::Fov},
    {"render.width", "Image width", Rule::Image},
    {"render.height", "Image height", Rule::Image},
    {"render.max_depth", "Max depth", Rule::Depth},
    {"render.samples_per_pixel", "Samples per pixel", Rule::Samples},
    {"background", "Background colour", Rule::Colour},
    {"ambient", "Ambient colour", Rule::Colour},
};

QString ruleText(Rule rule, const std::string& reason) {
    // Core's reason tells which of a vector's two rules failed.
    if (reason.starts_with("must be finite")) return QObject::tr("must be a finite number");
    switch (rule) {
        case Rule::Positive:
            return QObject::tr("must be greater than 0");
        case Rule::NonNegative:
            return QObject::tr("must not be negative");
        case Rule::UnitInterval:
            return QObject::tr("must be between 0 and 1");
        case Rule::Finite:
            return QObject::tr("must be a finite number");
        case Rule::Colour:
            return QObject::tr("must not have negative components");
        case Rule::Image:
            return QObject::tr("must be between 1 and %1 pixels").arg(kMaxImageSize);
        case Rule::Depth:
            return QObject::tr("must be between 0 and %1").arg(kMaxDepth);
        case Rule::Samples:
            return QObject::tr("must be between 1 and %1").arg(kMaxSamplesPerPixel);
        case Rule::Fov:
            return QObject::tr("must be between 0 and 180 degrees");
    }
    return {};
}

template <std::size_t N>
const FieldWords* findField(const FieldWords (&fields)[N], const QString& path) {
    for (const FieldWords& field : fields)
        if (path == QLatin1String(field.path)) return &field;
    return nullptr;
}

QString quotedName(const std::string& name) {
    return QStringLiteral("“%1”").arg(QString::fromStdString(name));
}

// The camera's two rules that are not about one value.
QString cameraText(const SceneProblem& problem) {
    if (problem.jsonPath == "camera.look_at" && problem.reason.starts_with("equals"))
        return QObject::tr("The camera's look-at point must differ from its position");
    if (problem.jsonPath == "camera.up" && problem.reason.starts_with("must not be zero"))
        return QObject::tr("The camera's up vector must not be zero");
    if (problem.jsonPath == "camera.up" && problem.reason.starts_with("is parallel"))
        return QObject::tr("The camera's up vector must not point along the view direction");
    return {};
}

// A problem with the name of item `index` of a list of `noun`s.
QString nameText(const QString& noun, const std::string& name) {
    if (name.empty()) return QObject::tr("A %1 needs a name").arg(noun);
    return QObject::tr("There is already a %1 named %2").arg(noun, quotedName(name));
}

template <class Item, std::size_t N>
QString itemText(const std::vector<Item>& items, int index, const QString& noun,
                 const FieldWords (&fields)[N], const QString& field, const SceneProblem& problem) {
    if (index < 0 || index >= static_cast<int>(items.size())) return {};
    const Item& item = items[index];
    if (field == QLatin1String("name")) return nameText(noun, item.name);
    const FieldWords* words = findField(fields, field);
    if (!words) return {};
    return QObject::tr("%1 of %2 %3 %4")
        .arg(QObject::tr(words->label), noun, quotedName(item.name),
             ruleText(words->rule, problem.reason));
}

QString sphereMaterialText(const Scene& scene, int index) {
    if (index < 0 || index >= static_cast<int>(scene.spheres.size())) return {};
    const Sphere& sphere = scene.spheres[index];
    return QObject::tr("Sphere %1 uses material %2, which does not exist")
        .arg(quotedName(sphere.name), quotedName(sphere.material));
}

QString listText(const SceneProblem& problem, const Scene& scene) {
    static const QRegularExpression itemPath(QStringLiteral("^(\\w+)\\[(\\d+)\\]\\.(.+)$"));
    const auto match = itemPath.match(QString::fromStdString(problem.jsonPath));
    if (!match.hasMatch()) return {};
    const QString list = match.captured(1), field = match.captured(3);
    const int index = match.captured(2).toInt();
    if (list == QLatin1String("spheres")) {
        if (field == QLatin1String("material")) return sphereMaterialText(scene, index);
        return itemText(scene.spheres, index, kindNoun(ItemKind::Sphere), kSphereFields, field,
                        problem);
    }
    if (list == QLatin1String("lights"))
        return itemText(scene.lights, index, kindNoun(ItemKind::Light), kLightFields, field,
                        problem);
    if (list == QLatin1String("materials"))
        return itemText(scene.materials, index, kindNoun(ItemKind::Material), kMaterialFields,
                        field, problem);
    return {};
}

QString sceneFieldText(const SceneProblem& problem) {
    const FieldWords* words = findField(kSceneFields, QString::fromStdString(problem.jsonPath));
    if (!words) return {};
    return QObject::tr("%1 %2").arg(QObject::tr(words->label),
                                    ruleText(words->rule, problem.reason));
}

}  // namespace

QString editProblemText(const SceneProblem& problem, const Scene& scene) {
    QString text = cameraText(problem);
    if (text.isEmpty()) text = listText(problem, scene);
    if (text.isEmpty()) text = sceneFieldText(problem);
    if (text.isEmpty()) return QString::fromStdString(problem.jsonPath + ": " + problem.reason);
    return text;
}

}  // namespace whitted::ui
