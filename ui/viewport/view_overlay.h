// What the render view draws over the picture: the selected spheres' outlines
// (the active one brighter; dots at their centres past kMostOutlines), the
// rays of the pixel the Ray Tree dock inspects,
// a marker for each light (lights have no surface to see; one outside the
// picture sits at its edge with an arrow towards it), the orbit's pivot
// while dragging, and the name of what is under the cursor. Positions come
// from core's projection (view_projection.h), so the marks sit exactly where
// the tracer puts the things they mark.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <QImage>
#include <QPoint>
#include <QRect>
#include <QString>

#include "camera/view_projection.h"
#include "document/scene_document.h"
#include "scene/scene.h"
#include "viewport/ray_tree_overlay.h"

class QPainter;

namespace whitted::ui {

// Where a large selection's dots go, kept from paint to paint: a frame
// repaints the view, and projecting 100,000 centres each time was a fifth of
// the editor's thread while a material was given to them. Valid while the
// camera, the picture's size, the spheres' geometry and the selection are
// those it was made for.
struct SelectionDots {
    Camera camera;
    int width = 0, height = 0;
    std::uint64_t geometryRevision = ~std::uint64_t(0);
    std::vector<int> indices;
    std::vector<ImagePoint> points;
    // The dots drawn once into an image the size of the picture's place in
    // the view, which each paint lays over the picture in one go: the raster
    // engine's drawPoints of 100,000 dots took half the editor's thread while
    // a material was given to them (each frame repaints). Null: to be drawn.
    QImage layer;
};

struct ViewOverlay {
    std::optional<Vec3> pivot;  // the orbit's pivot, drawn while a drag turns about it
    QString hoverText;          // empty: nothing under the cursor
    QPoint hoverPos;
    QRect box;                   // the box being dragged out to select with (B); empty: none
    std::vector<DrawnRay> rays;  // an inspected pixel's ray tree (the Ray Tree dock)
    int highlightedRay = -1;
    SelectionDots dots;
    std::uint64_t geometryRevision = 0;  // the document's, when painted
};

// Outlines cost a polygon each: a selection of more spheres shows dots.
inline constexpr int kMostOutlines = 2000;

// Draws the overlay for `scene` seen in `imageRect` (the picture's place in the widget).
// The overlay's dots are brought up to date as they are drawn.
void paintViewOverlay(QPainter& painter, const Scene& scene, const QRect& imageRect,
                      const SceneSelection& selection, ViewOverlay& overlay);

// The light whose marker covers widget point `pos` (the nearest if several), or -1.
int lightMarkerAt(const Scene& scene, const QRect& imageRect, const QPointF& pos);

// The widget point of a scene point, or nothing when it is behind the eye.
std::optional<QPointF> widgetPoint(const Scene& scene, const QRect& imageRect, const Vec3& p);

// Widget point to image point in pixels of the scene's render size.
QPointF imagePoint(const Scene& scene, const QRect& imageRect, const QPointF& widget);

}  // namespace whitted::ui
