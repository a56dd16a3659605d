// A scene field's words as the editor shows them, all from its one
// description (core/scene/scene_fields.h): in a refused edit's message, in a
// property panel's row and in an undo entry, so that they never disagree.
#pragma once

#include <QByteArray>
#include <QObject>
#include <QString>

#include <string_view>

#include "scene/scene_fields.h"

namespace whitted::ui {

inline QString translatedWords(std::string_view words) {
    return QObject::tr(QByteArray(words.data(), qsizetype(words.size())).constData());
}

// As a message names it: "Camera position".
inline QString fieldLabel(const SceneField& field) {
    return translatedWords(field.label);
}

// Its row in a property panel: "Position:" on the camera's page.
inline QString fieldRow(const SceneField& field) {
    return translatedWords(field.row.empty() ? field.label : field.row) + QLatin1Char(':');
}

// What an undo entry says is changed: "camera position".
inline QString fieldChanged(const SceneField& field) {
    return fieldLabel(field).toLower();
}

}  // namespace whitted::ui
