// The central view: shows the newest frame scaled to fit, keeping the scene's
// aspect ratio, and turns mouse and keys into camera moves and picks.
//
// Left drag orbits around look_at, right or middle drag pans, the wheel
// dollies; a click without a drag picks the sphere under the cursor. The keys
// (arrows orbit, W/A/S/D/Q/E walk, +/- zoom, Home resets to the scene's own
// camera, F frames the selected sphere) are QActions, listed by cameraActions():
// the actions are the one table that binds the keys, fills the View menu and
// the Keyboard and Mouse help, so the three cannot drift apart. Camera moves are
// document edits, a drag one undo step.
#pragma once

#include <QAction>
#include <QImage>
#include <QList>
#include <QPair>
#include <QPoint>
#include <QWidget>

#include "scene.h"

namespace whitted::ui {

class SceneDocument;

class RenderView : public QWidget {
    Q_OBJECT
  public:
    explicit RenderView(SceneDocument* doc, QWidget* parent = nullptr);

    void setFrame(const QImage& image);
    const QImage& frame() const { return frame_; }

    // The camera Home returns to: the scene's camera as it was opened or saved.
    void setHomeCamera(const Camera& camera) { home_ = camera; }
    // The sphere F frames; -1 for none.
    void setSelectedSphere(int index) { selectedSphere_ = index; }

    // Camera moves called directly (menus, toolbar, the key actions).
    void resetCamera();
    void frameSelectedSphere();

    // The keyboard's camera moves, each an action with its shortcut and an
    // object name. Reset and Frame have window-wide shortcuts (they sit in the
    // View menu); the others act while the view has the keyboard focus.
    const QList<QAction*>& cameraActions() const { return cameraActions_; }

    // What the mouse does in the view, for the help: (gesture, effect) pairs.
    static QList<QPair<QString, QString>> mouseControls();

    // Where the image is drawn inside the widget.
    QRect imageRect() const;

    QSize sizeHint() const override { return {800, 600}; }

  signals:
    void spherePicked(int index);  // -1: the click hit nothing

  protected:
    void paintEvent(QPaintEvent*) override;
    void mousePressEvent(QMouseEvent*) override;
    void mouseMoveEvent(QMouseEvent*) override;
    void mouseReleaseEvent(QMouseEvent*) override;
    void wheelEvent(QWheelEvent*) override;

  private:
    void moveCamera(const QString& text, const Camera& camera);
    void buildCameraActions();

    SceneDocument* doc_;
    QImage frame_;
    Camera home_;
    int selectedSphere_ = -1;
    QPoint pressPos_, lastPos_;
    Qt::MouseButton dragButton_ = Qt::NoButton;
    bool dragging_ = false;
    QList<QAction*> cameraActions_;
};

}  // namespace whitted::ui
