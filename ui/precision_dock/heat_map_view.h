// Shows the float-versus-double heat map scaled to fit, keeping its aspect ratio.
//
// Differences are often single pixels, so scaling must not lose them: enlarged,
// every image pixel becomes a crisp block; reduced, each screen pixel shows the
// brightest (the most different) image pixel it covers, not an average that
// would fade a lone bright pixel into the black around it.
#pragma once

#include <QImage>
#include <QWidget>

namespace whitted::ui {

class HeatMapView : public QWidget {
    Q_OBJECT
  public:
    explicit HeatMapView(QWidget* parent = nullptr);

    void setImage(const QImage& image);
    const QImage& image() const { return image_; }
    QRect imageRect() const;  // where the image is drawn inside the widget

    QSize sizeHint() const override { return {320, 240}; }
    QSize minimumSizeHint() const override { return {120, 90}; }

  protected:
    void paintEvent(QPaintEvent*) override;

  private:
    QImage image_;
    QImage reduced_;  // image_ reduced to the size last drawn, when smaller
};

// `image` reduced to `size` (each dimension at most the image's) keeping, for
// every output pixel, the brightest input pixel of the block it covers.
QImage reduceKeepingBrightest(const QImage& image, QSize size);

}  // namespace whitted::ui
