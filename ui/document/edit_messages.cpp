#include "document/edit_messages.h"

#include <QObject>

#include "document/field_words.h"
#include "document/scene_document.h"   // ItemKind, kindNoun, itemCount
#include "document/scene_selection.h"  // itemNameOf

namespace whitted::ui {

namespace {

// What a field must be, as the end of a sentence.
QString ruleText(FieldRule rule) {
    switch (rule) {
        case FieldRule::None:
        case FieldRule::Finite:
            return QObject::tr("must be a finite number");
        case FieldRule::Colour:
            return QObject::tr("must not have negative components");
        case FieldRule::Positive:
            return QObject::tr("must be greater than 0");
        case FieldRule::NonNegative:
            return QObject::tr("must not be negative");
        case FieldRule::UnitInterval:
            return QObject::tr("must be between 0 and 1");
        case FieldRule::ImageSize:
            return QObject::tr("must be between 1 and %1 pixels").arg(kMaxImageSize);
        case FieldRule::Depth:
            return QObject::tr("must be between 0 and %1").arg(kMaxDepth);
        case FieldRule::Samples:
            return QObject::tr("must be between 1 and %1").arg(kMaxSamplesPerPixel);
        case FieldRule::FieldOfView:
            return QObject::tr("must be between 0 and 180 degrees");
    }
    return {};
}

QString quotedName(const std::string& name) {
    return QStringLiteral("“%1”").arg(QString::fromStdString(name));
}

ItemKind kindOf(SceneList list) {
    if (list == SceneList::Materials) return ItemKind::Material;
    if (list == SceneList::Lights) return ItemKind::Light;
    return ItemKind::Sphere;
}

// The name of the item a problem is in; null when it is in none.
const std::string* itemName(const SceneProblem& problem, const Scene& scene) {
    if (problem.list == SceneList::None) return nullptr;
    const ItemKind kind = kindOf(problem.list);
    const int index = static_cast<int>(problem.index);
    if (index >= itemCount(scene, kind)) return nullptr;
    return &itemNameOf(scene, kind, index);
}

// A value against its field's rule: "Radius of sphere “ball” must be greater than 0".
QString valueText(const SceneProblem& problem, const Scene& scene) {
    if (!problem.field) return {};
    const QString rule =
        ruleText(problem.kind == ProblemKind::NotFinite ? FieldRule::Finite : problem.field->rule);
    if (problem.list == SceneList::None)
        return QObject::tr("%1 %2").arg(fieldLabel(*problem.field), rule);
    const std::string* name = itemName(problem, scene);
    if (!name) return {};
    return QObject::tr("%1 of %2 %3 %4")
        .arg(fieldLabel(*problem.field), kindNoun(kindOf(problem.list)), quotedName(*name), rule);
}

QString problemText(const SceneProblem& problem, const Scene& scene) {
    const QString noun = kindNoun(kindOf(problem.list));
    const std::string* name = itemName(problem, scene);
    switch (problem.kind) {
        case ProblemKind::BreaksRule:
        case ProblemKind::NotFinite:
            return valueText(problem, scene);
        case ProblemKind::LookAtIsPosition:
            return QObject::tr("The camera's look-at point must differ from its position");
        case ProblemKind::UpIsZero:
            return QObject::tr("The camera's up vector must not be zero");
        case ProblemKind::UpAlongView:
            return QObject::tr("The camera's up vector must not point along the view direction");
        case ProblemKind::EmptyName:
            return QObject::tr("A %1 needs a name").arg(noun);
        case ProblemKind::RepeatedName:
            if (!name) return {};
            return QObject::tr("There is already a %1 named %2").arg(noun, quotedName(*name));
        case ProblemKind::UnknownMaterial:
            if (!name) return {};
            return QObject::tr("Sphere %1 uses material %2, which does not exist")
                .arg(quotedName(*name), quotedName(scene.spheres[problem.index].material));
    }
    return {};
}

}  // namespace

QString editProblemText(const SceneProblem& problem, const Scene& scene) {
    const QString text = problemText(problem, scene);
    if (!text.isEmpty()) return text;
    if (problem.jsonPath.empty()) return QString::fromStdString(problem.reason);
    return QString::fromStdString(problem.jsonPath + ": " + problem.reason);
}

}  // namespace whitted::ui
