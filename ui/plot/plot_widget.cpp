#include "plot/plot_widget.h"

#include <QHelpEvent>
#include <QPainter>
#include <QToolTip>

#include <utility>

namespace whitted::ui {

namespace {
constexpr double kHoverRadius = 7.0;  // pixels: a little more than a marker
}  // namespace

PlotWidget::PlotWidget(QWidget* parent) : QWidget(parent) {
    setAttribute(Qt::WA_OpaquePaintEvent);  // paintPlot fills its whole rectangle
}

void PlotWidget::setPlot(PlotSpec spec, std::vector<QString> tooltips) {
    spec_ = std::move(spec);
    tooltips_ = std::move(tooltips);
    update();
}

QString PlotWidget::tooltipAt(QPointF pos) const {
    const PlotLayout layout = plotLayout(QRectF(rect()), spec_, font());
    const auto i = pointNear(layout, spec_, pos, kHoverRadius);
    if (!i) return {};
    return *i < tooltips_.size() ? tooltips_[*i] : spec_.points[*i].label;
}

bool PlotWidget::event(QEvent* e) {
    if (e->type() != QEvent::ToolTip) return QWidget::event(e);
    auto* help = static_cast<QHelpEvent*>(e);
    const QString text = tooltipAt(help->pos());
    if (text.isEmpty()) {
        QToolTip::hideText();
        e->ignore();
    } else {
        QToolTip::showText(help->globalPos(), text, this);
    }
    return true;
}

void PlotWidget::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setFont(font());
    paintPlot(painter, QRectF(rect()), spec_);
}

}  // namespace whitted::ui
