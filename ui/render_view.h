// The central view: shows the newest frame scaled to fit, keeping the scene's
// aspect ratio, and turns mouse and keys into camera moves and picks.
//
// Left drag orbits around look_at, right or middle drag pans, the wheel
// dollies; arrows orbit, W/A/S/D/Q/E walk, +/- zoom, Home resets to the scene's
// own camera, F frames the selected sphere. A click without a drag picks the
// sphere under the cursor. Camera moves are document edits, a drag one undo step.
#pragma once

#include <QImage>
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
    void keyPressEvent(QKeyEvent*) override;

  private:
    void moveCamera(const QString& text, const Camera& camera);

    SceneDocument* doc_;
    QImage frame_;
    Camera home_;
    int selectedSphere_ = -1;
    QPoint pressPos_, lastPos_;
    Qt::MouseButton dragButton_ = Qt::NoButton;
    bool dragging_ = false;
};

}  // namespace whitted::ui
