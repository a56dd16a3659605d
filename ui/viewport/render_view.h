// The central view: shows the newest frame scaled to fit, keeping the scene's
// aspect ratio, and turns mouse and keys into camera moves and picks.
//
// Left drag orbits about the surface point under the cursor where the drag
// starts, right or middle drag pans, the wheel dollies towards what is under
// the cursor; a click without a drag picks the sphere or light under it. The keys
// (arrows orbit, W/A/S/D/Q/E walk, +/- zoom, Home resets to the scene's own
// camera, F frames the selected sphere) are QActions, listed by cameraActions():
// the actions are the one table that binds the keys, fills the View menu and
// the Keyboard and Mouse help, so the three cannot drift apart. The arrows turn
// about the pivot: the selected sphere after F, else the point the last drag
// turned about, else the surface at the view's centre, else look_at. Up (key or
// drag) raises the eye, Left (key or drag) takes it to the left round the pivot.
// Camera moves are document edits: a drag, or a run of keys or wheel ticks less
// than half a second apart, is one undo step. Over the picture the view draws
// the selection, the lights and the name under the cursor (view_overlay.h).
//
// G moves the selected sphere or light with the pointer, as in Blender: in the
// plane through it facing the camera, the point grabbed staying under the
// pointer; X, Y or Z constrains it to that world axis (again: free again); a
// typed number moves it by exactly that much along the axis (X when none);
// Ctrl snaps the offset to a grid of kMoveGrid. A click or Enter keeps the
// move, one undo step; Escape or a right click puts the item back exactly and
// leaves no step. While it lasts every key is the move's, not a shortcut's.
#pragma once

#include <QAction>
#include <QImage>
#include <QList>
#include <QPair>
#include <QPoint>
#include <QWidget>

#include <optional>

#include "document/scene_document.h"
#include "scene/scene.h"
#include "viewport/view_overlay.h"

namespace whitted::ui {

class RenderView : public QWidget {
    Q_OBJECT
  public:
    explicit RenderView(SceneDocument* doc, QWidget* parent = nullptr);

    // `shown`: the part of `image` that covers the render, in its pixels (a
    // preview's last blocks may reach past the render's edge); empty: all of it.
    void setFrame(const QImage& image, QSizeF shown = {});
    const QImage& frame() const { return frame_; }

    // The camera Home returns to: the scene's camera as it was opened or saved.
    void setHomeCamera(const Camera& camera);
    // What the scene panel selects: outlined (a sphere) or ringed (a light) in
    // the view; a sphere is what F frames. Index -1 for none.
    void setSelection(ItemKind kind, int index);

    // Camera moves called directly (menus, toolbar, the key actions).
    void resetCamera();
    void frameSelectedSphere();

    // Starts moving the selected sphere or light with the pointer (G); false,
    // and nothing, when neither is selected.
    bool startMove();
    // Where a sphere of `radius` added at the pointer goes: resting on the
    // surface under it (the floor, a ball); nothing when the pointer is not
    // over the picture or sees only the sky.
    std::optional<Vec3> restingSpotUnderPointer(double radius) const;
    bool moving() const { return move_.has_value(); }
    // The grid Ctrl snaps a move to, in scene units.
    static constexpr double kMoveGrid = 0.1;

    // The keyboard's camera moves, each an action with its shortcut and an
    // object name. Reset, Frame and Move have window-wide shortcuts (they sit
    // in the View menu); the others act while the view has the keyboard focus.
    const QList<QAction*>& cameraActions() const { return cameraActions_; }

    // What the mouse does in the view, for the help: (gesture, effect) pairs.
    static QList<QPair<QString, QString>> mouseControls();

    // The name shown for what is under the cursor; empty when nothing is.
    QString hoverText() const { return overlay_.hoverText; }

    // Where the image is drawn inside the widget.
    QRect imageRect() const;

    QSize sizeHint() const override { return {800, 600}; }

  signals:
    // A click picked a sphere or light; index -1: the click hit nothing.
    void picked(whitted::ui::ItemKind kind, int index);
    // What a move in progress does and which keys it takes, for the status
    // bar; empty when the move ends.
    void moveMessage(const QString& text);
    // A move ended, kept or put back.
    void moveFinished();

  protected:
    void paintEvent(QPaintEvent*) override;
    void mousePressEvent(QMouseEvent*) override;
    void mouseMoveEvent(QMouseEvent*) override;
    void mouseReleaseEvent(QMouseEvent*) override;
    void wheelEvent(QWheelEvent*) override;
    void leaveEvent(QEvent*) override;
    bool event(QEvent*) override;
    void keyPressEvent(QKeyEvent*) override;
    void keyReleaseEvent(QKeyEvent*) override;

  private:
    void moveCamera(const QString& text, const Camera& camera, EditRun run = EditRun::Join);
    void buildCameraActions();
    // The sphere or light under a widget point (lights first: their markers
    // sit in front of everything); index -1 for nothing.
    QPair<ItemKind, int> itemAt(const QPointF& pos) const;
    // The surface point seen at a widget point, if any.
    std::optional<Vec3> surfaceAt(const QPointF& pos) const;
    // What the arrow keys turn about (see the header comment).
    Vec3 keyPivot() const;
    void updateHover(const QPoint& pos);

    // A move in progress (G): what moves, from where, and how.
    struct ItemMove {
        ItemKind kind;
        int index;
        Vec3 start;               // the item's position before the move, restored by Escape
        QPointF from;             // the image point the pointer grabbed
        QPoint pointer;           // where the pointer is now, in the widget
        std::optional<int> axis;  // 0 x, 1 y, 2 z; none: the plane facing the camera
        QString typed;            // a distance typed during the move
        bool snap = false;        // Ctrl held
        bool recorded = false;    // the gesture has begun: the item has moved
    };
    Vec3 moveOffset() const;
    void applyMove();
    void setItemPosition(const ItemMove& move, const Vec3& position);
    void finishMove(bool keep);
    // The undo step's name, "Move blue ball".
    QString moveStepName(const ItemMove& move) const;
    QString moveText(const Vec3& offset) const;

    SceneDocument* doc_;
    QImage frame_;
    QRectF frameShown_;  // the part of frame_ drawn into imageRect()
    Camera home_;
    ViewOverlay overlay_;
    std::optional<Vec3> pivot_;  // set by F and by an orbit drag; cleared by Home, pan, walk
    QPoint pressPos_, lastPos_;
    Qt::MouseButton dragButton_ = Qt::NoButton;
    bool dragging_ = false;
    QPoint pointer_{-1, -1};  // the pointer's last place in the view
    std::optional<ItemMove> move_;
    QList<QAction*> cameraActions_;
};

}  // namespace whitted::ui
