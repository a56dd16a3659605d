// The "Ray Tree" dock: why one pixel looks as it does. Ctrl+click on a pixel
// in the render view (or View > Ray Tree, then Ctrl+click) lists that pixel's
// one-sample ray tree as Whitted's paper draws it: the camera ray, then at
// each hit a shadow ray towards every light, the refracted and the reflected
// ray; what each hit, how far, the weight its path passes on and what it adds
// to the pixel; rays the maximum depth cut off, with what they would have
// added. Beside each figure, the same ray traced in the other precision,
// marked where the two differ by an 8-bit step or hit different things.
//
// It follows the scene: every change traces the same place of the picture
// again (on its thread, RayTreeWorker). The view draws the tree over the
// picture (ray_tree_overlay.h), the selected row's ray highlighted.
#pragma once

#include <optional>
#include <vector>

#include <QPointF>
#include <QWidget>

#include "ray_tree_dock/ray_tree_worker.h"
#include "viewport/ray_tree_overlay.h"

class QLabel;
class QTreeWidget;
class QTreeWidgetItem;

namespace whitted::ui {

class SceneDocument;

class RayTreeView : public QWidget {
    Q_OBJECT
  public:
    explicit RayTreeView(SceneDocument* doc, QWidget* parent = nullptr);

    // Inspects pixel (x, y) of the scene's picture, and again after each
    // change: the same place of the picture if its size changes.
    void inspect(QPoint pixel);
    // The pixel inspected at the scene's size; none before the first.
    std::optional<QPoint> pixel() const;
    const RayTreeResult& shownResult() const { return shown_; }

    // What the view draws: the shown tree's rays, and the selected row's.
    const std::vector<DrawnRay>& rays() const { return rays_; }
    int highlightedRay() const { return highlighted_; }

  signals:
    // A new tree is listed (its generation): the overlay and the summary changed.
    void treeShown(quint64 generation);
    // The rays to draw or the highlighted one changed.
    void overlayChanged();

  protected:
    void hideEvent(QHideEvent*) override;
    void showEvent(QShowEvent*) override;

  private:
    void trace();
    void onTree(const RayTreeResult& result);
    // The tree in the scene's precision, and in the other one.
    const PixelRayTree& own() const;
    const PixelRayTree& other() const;
    void fillRows();
    QTreeWidgetItem* addRow(QTreeWidgetItem* parent, const RayTreeNode& node,
                            const RayTreeNode* other, int& rayIndex);
    QString summary() const;

    SceneDocument* doc_;
    RayTreeWorker worker_;
    std::optional<QPointF> place_;  // the pixel's centre as a fraction of the picture
    RayTreeResult shown_;
    std::vector<DrawnRay> rays_;
    int highlighted_ = -1;
    QLabel* summary_;
    QTreeWidget* rows_;
};

}  // namespace whitted::ui
