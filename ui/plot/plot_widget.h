// A widget that paints a PlotSpec (scatter_plot.h) to its size and shows a
// tooltip for the point under the cursor.
#pragma once

#include <QString>
#include <QWidget>

#include <vector>

#include "plot/scatter_plot.h"

namespace whitted::ui {

class PlotWidget : public QWidget {
    Q_OBJECT
  public:
    explicit PlotWidget(QWidget* parent = nullptr);

    // `tooltips` parallels spec.points; a point without one shows its label.
    void setPlot(PlotSpec spec, std::vector<QString> tooltips = {});
    const PlotSpec& spec() const { return spec_; }
    // The tooltip of the point nearest to `pos` (widget pixels), empty if none is near.
    QString tooltipAt(QPointF pos) const;

    QSize sizeHint() const override { return {420, 300}; }
    QSize minimumSizeHint() const override { return {240, 160}; }

  protected:
    bool event(QEvent* e) override;
    void paintEvent(QPaintEvent*) override;

  private:
    PlotSpec spec_;
    std::vector<QString> tooltips_;
};

}  // namespace whitted::ui
