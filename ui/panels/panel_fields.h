// What the property pages share: field specs, bound fields built from one
// accessor, and the form layout.
#pragma once

#include <functional>
#include <limits>
#include <optional>
#include <vector>

#include <QString>

#include "document/scene_document.h"
#include "panels/number_field.h"

class QFormLayout;
class QLabel;
class QWidget;

namespace whitted::ui {

// Positions, directions and lengths: every finite value the file format allows
// (scenes/extremes/ holds floors of radius 1e9 and balls of radius 5e-5), so a
// value from a file is never clamped on display or on the next edit.
inline constexpr double kLargest = std::numeric_limits<double>::max();
inline const DoubleFieldSpec kCoordinate = DoubleFieldSpec::range(-kLargest, kLargest, 0.1);
// A length's spin box takes 0, so that a typed 0 is refused with the reason
// ("must be greater than 0") rather than quietly clamped to the smallest double.
// Its slider is logarithmic over six decades: a 0.05 marble and a 100-unit dome
// both sit inside it, and one step changes either by the same few percent.
inline const DoubleFieldSpec kPositiveLength =
    DoubleFieldSpec::range(0.0, kLargest, 0.1).adaptive();
inline const DoubleFieldSpec kLength = kPositiveLength.logSlider(0.001, 1000.0);
inline const DoubleFieldSpec kUnitInterval =
    DoubleFieldSpec::range(0.0, 1.0, 0.05).linearSlider(0.0, 1.0);

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
        sceneCommit([access](Scene& s, double value) {
            if (double* v = access(s)) *v = value;
        }),
        std::move(text));
    fields.push_back(field);
    return field;
}

// Which item of type T (Sphere, Light, Material) a page's fields edit: its
// index in its list, found in the scene (-1 or out of range: none).
using Locate = std::function<int(const Scene&)>;
// Which items a page's fields edit at once: the shown item first, then the
// rest of the selection it belongs to.
using Targets = std::function<std::vector<int>(const Scene&)>;

// The shown item of `kind`, then the other selected items when the shown one
// is selected with them: what a property page's edit changes.
std::vector<int> editTargets(const SceneDocument& doc, ItemKind kind, int shown);

// A field for the double that `access(item)` points to (nullptr: none) in the
// items `targets` finds: it shows the first one's value, "mixed" when the
// others differ, and sets them all in one item edit
// (SceneDocument::editItems), in time proportional to the items, not the scene.
template <class T, class Access>
DoubleField* makeItemsField(SceneDocument* doc, const QString& name, const DoubleFieldSpec& spec,
                            Targets targets, Access access, DoubleField::TextFn text,
                            std::vector<DoubleField*>& fields) {
    auto valueOf = [access](const Scene& s, int i) -> std::optional<double> {
        const T* item = itemAt(itemsOf<T>(s), i);
        const double* v = item ? access(*item) : nullptr;
        return v ? std::optional<double>(*v) : std::nullopt;
    };
    auto* field = new DoubleField(
        doc, name, spec,
        [targets, valueOf](const Scene& s) {
            const std::vector<int> items = targets(s);
            return items.empty() ? 0.0 : valueOf(s, items.front()).value_or(0.0);
        },
        [targets, access](SceneDocument& d, const QString& text, double value, QString* error) {
            return d.editItems<T>(
                targets(d.scene()), text,
                [&](T& item, int) {
                    if (double* v = access(item)) *v = value;
                },
                error);
        },
        std::move(text));
    field->setMixedOf([targets, valueOf](const Scene& s) {
        const std::vector<int> items = targets(s);
        for (std::size_t k = 1; k < items.size(); ++k)
            if (valueOf(s, items[k]) != valueOf(s, items.front())) return true;
        return false;
    });
    fields.push_back(field);
    return field;
}

// makeItemsField for the one item `locate` finds.
template <class T, class Access>
DoubleField* makeItemField(SceneDocument* doc, const QString& name, const DoubleFieldSpec& spec,
                           Locate locate, Access access, DoubleField::TextFn text,
                           std::vector<DoubleField*>& fields) {
    return makeItemsField<T>(
        doc, name, spec, [locate](const Scene& s) { return std::vector<int>{locate(s)}; }, access,
        std::move(text), fields);
}

// Three fields in a row, named <name>X, <name>Y, <name>Z, made by `field(axis,
// objectName)`.
QWidget* makeVectorRow(const QString& name,
                       const std::function<DoubleField*(int axis, const QString& name)>& field,
                       std::vector<DoubleField*>& fields);

// A row for the Vec3 that `access(scene)` points to (nullptr: none); one
// generic accessor for both constnesses.
template <class Access>
QWidget* makeVectorRow(SceneDocument* doc, const QString& name, const DoubleFieldSpec& spec,
                       Access access, const DoubleField::TextFn& text,
                       std::vector<DoubleField*>& fields) {
    return makeVectorRow(
        name,
        [&](int axis, const QString& objectName) {
            return new DoubleField(
                doc, objectName, spec,
                [access, axis](const Scene& s) {
                    const Vec3* v = access(s);
                    return v ? (*v)[axis] : 0.0;
                },
                sceneCommit([access, axis](Scene& s, double value) {
                    if (Vec3* v = access(s)) (*v)[axis] = value;
                }),
                text);
        },
        fields);
}

// A row for the Vec3 that `access(item)` points to in the items `targets`
// finds, edited as makeItemsField's fields are.
template <class T, class Access>
QWidget* makeItemsVectorRow(SceneDocument* doc, const QString& name, const DoubleFieldSpec& spec,
                            Targets targets, Access access, const DoubleField::TextFn& text,
                            std::vector<DoubleField*>& fields) {
    return makeVectorRow(
        name,
        [&](int axis, const QString& objectName) {
            std::vector<DoubleField*> one;
            return makeItemsField<T>(
                doc, objectName, spec, targets,
                [access, axis](auto& item) {
                    auto* v = access(item);
                    return v ? &(*v)[axis] : nullptr;
                },
                text, one);
        },
        fields);
}

QFormLayout* makeForm(QWidget* page);
QLabel* makeNameLabel(const QString& objectName);
void refreshAll(const std::vector<DoubleField*>& fields);

}  // namespace whitted::ui
