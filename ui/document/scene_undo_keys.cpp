#include "document/scene_undo_keys.h"

#include <QApplication>
#include <QKeyEvent>
#include <QWidget>

namespace whitted::ui {

SceneUndoKeys::SceneUndoKeys(QWidget* window, QList<QAction*> actions)
    : QObject(window), window_(window), actions_(std::move(actions)) {
    qApp->installEventFilter(this);
}

bool SceneUndoKeys::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() != QEvent::ShortcutOverride) return false;
    auto* widget = qobject_cast<QWidget*>(watched);
    if (!widget || widget->window() != window_) return false;
    const QKeySequence pressed(static_cast<QKeyEvent*>(event)->keyCombination());
    // Swallowed unaccepted, the override lets the window's Undo and Redo
    // shortcuts fire instead of the field's own text undo.
    for (const QAction* action : actions_)
        if (action->isEnabled() && action->shortcuts().contains(pressed)) return true;
    return false;
}

}  // namespace whitted::ui
