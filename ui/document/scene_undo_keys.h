// Scene undo and redo from the keyboard wherever the focus is. A spin box or
// line edit that was just typed into claims Ctrl+Z for its own text undo (by
// accepting the ShortcutOverride event), so the scene's Undo never fired while
// the focus stayed in the field. The scene's fields commit on every keystroke,
// so the scene's undo is the one the user means.
#pragma once

#include <QAction>
#include <QList>
#include <QObject>

namespace whitted::ui {

class SceneUndoKeys : public QObject {
    Q_OBJECT
  public:
    // Watches the application's key events for widgets inside `window`, and
    // lets the shortcuts of `actions` (the scene's Undo and Redo) win there.
    SceneUndoKeys(QWidget* window, QList<QAction*> actions);

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    QWidget* window_;
    QList<QAction*> actions_;
};

}  // namespace whitted::ui
