// The central view: shows the newest frame scaled to fit, keeping the scene's
// aspect ratio, and turns mouse and keys into camera moves and picks.
//
// Left drag orbits about the surface point under the cursor where the drag
// starts, right or middle drag pans, the wheel dollies towards what is under
// the cursor; a click without a drag picks the sphere or light under it. The keys
// (arrows orbit, W/A/S/D/Q/E walk in fly mode, +/- zoom, Home resets to the
// scene's own camera, F frames the selected sphere, G moves, S scales, B boxes)
// are QActions, listed by cameraActions():
// the actions are the one table that binds the keys, fills the View menu and
// the Keyboard and Mouse help, so the three cannot drift apart. The arrows turn
// about the pivot: the selected sphere after F, else the point the last drag
// turned about, else the surface at the view's centre, else look_at. Up (key or
// drag) raises the eye, Left (key or drag) takes it to the left round the pivot.
// Camera moves are document edits: a drag, or a run of keys or wheel ticks less
// than half a second apart, is one undo step. Over the picture the view draws
// the selection, the lights and the name under the cursor (view_overlay.h).
//
// Alt+left drag on a selected item moves the selection
// (as G does, kept on release). Click selects what is under the pointer,
// Shift+click adds it to the selection or takes it out; B, then a drag,
// selects the spheres and lights inside the box (Shift: adds to the selection).
// Ctrl+click inspects the pixel under the pointer (the Ray Tree dock).
//
// G moves the selection with the pointer, as in Blender: in the plane through
// the active item facing the camera, the point grabbed staying under the
// pointer; X, Y or Z constrains it to that world axis (again: free again); a
// typed number moves it by exactly that much along the axis (X when none);
// Ctrl snaps the offset to the snap step (kMoveGrid unless the user set
// another, View > Snap Step); Shift drops a sphere onto what
// is under the pointer (resting on the floor or touching a ball). S scales the
// selected spheres' radii by how far the pointer is from their middle on
// screen against where it started (a typed number: by that factor; Ctrl: in
// steps of 0.1). A click or Enter keeps the change, one undo step; Escape or a
// right click puts everything back exactly and leaves no step. While it lasts
// every key is the gesture's, not a shortcut's.
//
// Shift+` enters fly mode, where W/S go forward and back, A/D left and right,
// E/Q up and down (Blender's walk keys, kept out of the way of its A, S and
// G); Escape or Shift+` again leaves it.
#pragma once

#include <QAction>
#include <QImage>
#include <QList>
#include <QPair>
#include <QPoint>
#include <QWidget>

#include <functional>
#include <optional>
#include <vector>

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

    // Camera moves called directly (menus, toolbar, the key actions).
    void resetCamera();
    void frameSelectedSphere();

    // Starts moving the selected spheres or lights with the pointer (G);
    // false, and nothing, when none is selected.
    bool startMove();
    // Starts scaling the selected spheres' radii with the pointer (S); false,
    // and nothing, when no sphere is selected.
    bool startScale();
    // Waits for a drag that selects what lies inside its box (B).
    void startBoxSelect();
    bool flying() const { return flying_; }
    void setFlying(bool on);
    // Where a sphere of `radius` added at the pointer goes: resting on the
    // surface under it (the floor, a ball); nothing when the pointer is not
    // over the picture or sees only the sky.
    std::optional<Vec3> restingSpotUnderPointer(double radius) const;
    bool moving() const { return move_.has_value(); }
    // The factor S keeps to: how many times each radius is multiplied by.
    static constexpr double kScaleSnap = 0.1;
    // The grid Ctrl snaps a move to, in scene units, unless the user sets another.
    static constexpr double kMoveGrid = 0.1;
    double moveGrid() const { return moveGrid_; }
    void setMoveGrid(double step) { moveGrid_ = step > 0 ? step : kMoveGrid; }

    // The keyboard's camera moves, each an action with its shortcut and an
    // object name. Reset, Frame and Move have window-wide shortcuts (they sit
    // in the View menu); the others act while the view has the keyboard focus.
    const QList<QAction*>& cameraActions() const { return cameraActions_; }

    // What the mouse does in the view, for the help: (gesture, effect) pairs.
    static QList<QPair<QString, QString>> mouseControls();

    // The rays drawn over the picture: an inspected pixel's tree, `highlighted`
    // (an index into rays, or -1) drawn over the others.
    void setInspectedRays(std::vector<DrawnRay> rays, int highlighted);

    // The name shown for what is under the cursor; empty when nothing is.
    QString hoverText() const { return overlay_.hoverText; }

    // Where the image is drawn inside the widget.
    QRect imageRect() const;

    QSize sizeHint() const override { return {800, 600}; }

  signals:
    // What a move in progress does and which keys it takes, for the status
    // bar; empty when the move ends.
    void moveMessage(const QString& text);
    // A move or scale ended, kept or put back.
    void moveFinished();
    // Ctrl+click on the picture: pixel (x, y) of the scene's render size.
    void pixelInspected(QPoint pixel);

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

    // A move (G) or scale (S) in progress: what changes, from what, and how.
    enum class Gesture { Move, Scale };
    struct ItemMove {
        Gesture gesture;
        ItemKind kind;
        std::vector<int> indices;   // the selection's, ascending
        std::vector<Vec3> starts;   // each item's position before, restored by Escape
        std::vector<double> radii;  // each sphere's radius before (a scale)
        Vec3 anchor;                // the active item's position, which the pointer drags
        Vec3 depth;                 // a point of the plane the pointer moves things in
        QPointF from;               // the image point the pointer grabbed
        QPointF grabbed;            // the same in the widget
        QPoint pointer;             // where the pointer is now, in the widget
        QPointF middle;             // a scale's centre on screen, in the widget
        std::optional<int> axis;    // 0 x, 1 y, 2 z; none: the plane facing the camera
        QString typed;              // a distance or factor typed during the gesture
        bool snap = false;          // Ctrl held
        bool drop = false;          // Shift held: onto what is under the pointer
        bool byDrag = false;        // Alt+drag: kept when the button is released
        bool recorded = false;      // the gesture has begun: something has changed
    };
    bool beginGesture(Gesture gesture, bool byDrag);
    Vec3 moveDepth(const ItemMove& m) const;
    Vec3 moveOffset() const;
    std::optional<Vec3> dropOffset() const;
    double scaleFactor() const;
    void applyMove();
    void setPositions(const ItemMove& move, const std::function<Vec3(int k)>& position);
    void setRadii(const ItemMove& move, const std::function<double(int k)>& radius);
    void putBack(const ItemMove& move);
    bool changedSinceStart(const ItemMove& move) const;
    void finishMove(bool keep);
    void gestureKey(QKeyEvent* e);
    // The undo step's name, "Move blue ball", "Scale 3 spheres".
    QString moveStepName(const ItemMove& move) const;
    QString moveText() const;
    // Click and box selection.
    void clickSelect(const QPointF& pos, bool toggle);
    void inspectPixel(const QPointF& pos);
    void boxSelect(const QRect& box, bool add);
    void flyKey(QKeyEvent* e);

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
    bool boxWaiting_ = false;  // B pressed: the next left drag draws a box
    bool flying_ = false;
    double moveGrid_ = kMoveGrid;
    QList<QAction*> walkActions_;  // enabled in fly mode alone
    QList<QAction*> cameraActions_;
};

}  // namespace whitted::ui
