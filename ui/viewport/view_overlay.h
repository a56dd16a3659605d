// What the render view draws over the picture: the selected sphere's outline,
// a marker for each light (lights have no surface to see; one outside the
// picture sits at its edge with an arrow towards it), the orbit's pivot
// while dragging, and the name of what is under the cursor. Positions come
// from core's projection (view_projection.h), so the marks sit exactly where
// the tracer puts the things they mark.
#pragma once

#include <optional>

#include <QPoint>
#include <QRect>
#include <QString>

#include "document/scene_document.h"
#include "scene/scene.h"

class QPainter;

namespace whitted::ui {

struct ViewOverlay {
    ItemKind selectedKind = ItemKind::Sphere;
    int selectedIndex = -1;     // -1: nothing selected
    std::optional<Vec3> pivot;  // the orbit's pivot, drawn while a drag turns about it
    QString hoverText;          // empty: nothing under the cursor
    QPoint hoverPos;
};

// Draws the overlay for `scene` seen in `imageRect` (the picture's place in the widget).
void paintViewOverlay(QPainter& painter, const Scene& scene, const QRect& imageRect,
                      const ViewOverlay& overlay);

// The light whose marker covers widget point `pos` (the nearest if several), or -1.
int lightMarkerAt(const Scene& scene, const QRect& imageRect, const QPointF& pos);

// The widget point of a scene point, or nothing when it is behind the eye.
std::optional<QPointF> widgetPoint(const Scene& scene, const QRect& imageRect, const Vec3& p);

// Widget point to image point in pixels of the scene's render size.
QPointF imagePoint(const Scene& scene, const QRect& imageRect, const QPointF& widget);

}  // namespace whitted::ui
