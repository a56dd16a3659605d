// Help > Keyboard and Mouse and Help > About.
//
// The keyboard table is read from the window's own actions, the objects whose
// shortcuts are bound, so the help cannot drift from what the keys do.
#pragma once

#include <QList>
#include <QPair>
#include <QString>

class QAction;
class QDialog;
class QWidget;

namespace whitted::ui {

// One row of the keyboard and mouse help: where it lives, the keys, what it does.
struct ControlRow {
    QString group;  // "File", "Camera (in the view)", "Mouse (in the view)"
    QString keys;   // "Ctrl+S", "Left, Right"; the gesture for mouse rows
    QString action;
    bool mouse = false;  // a gesture, not keys
};

// Every action of `window` (menus, toolbar, the view's keys) that has a
// shortcut, grouped by the menu it is in, followed by the mouse controls.
QList<ControlRow> controlRows(QWidget* window, const QList<QPair<QString, QString>>& mouse);

// The dialogs, window-modal and deleted on close. Object names
// "keyboardHelp" (its table "controlsTable") and "aboutBox".
QDialog* showKeyboardHelp(QWidget* window, const QList<ControlRow>& rows);
QDialog* showAbout(QWidget* window);

// Adds each action's shortcut to its tool tip ("Save (Ctrl+S)"), for every
// action under `root` that has one.
void addShortcutsToToolTips(QWidget* root);

// Gives every input of a form under `root` that has no tool tip one named
// after its row ("Radius"; "Centre: x" for a vector's parts), so that hovering
// any field says what it edits.
void addFieldToolTips(QWidget* root);

}  // namespace whitted::ui
