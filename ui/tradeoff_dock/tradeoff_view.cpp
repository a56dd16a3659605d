// TradeoffView: building the dock, arranging the plot beside or above the
// tables, and what pinning and measuring share. Pinning and scoring renders
// are in tradeoff_view_pinning.cpp, Measure in tradeoff_view_measure.cpp.
#include "tradeoff_dock/tradeoff_view.h"

#include <QAction>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QResizeEvent>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>

#include "document/scene_document.h"
#include "plot/plot_widget.h"
#include "prediction/render_record.h"
#include "prediction/settings_prediction.h"
#include "tradeoff_dock/tradeoff_plot_spec.h"
#include "tradeoff_dock/tradeoff_tables.h"

namespace whitted::ui {

namespace {

// Measure's points arrive every few milliseconds on small scenes: the plot and
// the table follow at most this often.
constexpr int kLiveRefreshMs = 200;
// Narrower than this, a plot's labels crowd out its points.
constexpr int kMinPlotWidth = 360;

QLabel* makeStatus(const QString& name) {
    auto* label = new QLabel;
    label->setObjectName(name);
    label->setWordWrap(true);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

QToolButton* makeButton(QAction* action) {
    auto* button = new QToolButton;
    button->setDefaultAction(action);
    button->setToolButtonStyle(Qt::ToolButtonTextOnly);
    return button;
}

}  // namespace

QString TradeoffView::sizeText(int w, int h) {
    return QObject::tr("%1 × %2").arg(w).arg(h);
}

TradeoffView::TradeoffView(SceneDocument* doc, RenderRecord* record, QWidget* parent)
    : QWidget(parent),
      doc_(doc),
      record_(record),
      grid_(editorMeasureGrid()),
      referenceSamples_(kEditorReferenceSamples) {
    buildActions();
    buildWidgets();
    buildLayout();
    connectUpdates();
    updateActions();
    updatePinStatus();
    updateMeasureStatus();
    refreshPlot();
}

void TradeoffView::buildActions() {
    pin_ = new QAction(tr("&Pin as Reference"), this);
    pin_->setObjectName(QStringLiteral("pinReference"));
    pin_->setToolTip(
        tr("Keep the finished image and its settings; every later render is "
           "compared with it"));
    unpin_ = new QAction(tr("&Unpin"), this);
    unpin_->setObjectName(QStringLiteral("unpinReference"));
    unpin_->setToolTip(tr("Drop the pinned image and the points compared with it"));
    measure_ = new QAction(tr("&Measure Trade-off…"), this);
    measure_->setObjectName(QStringLiteral("measureTradeoff"));
    measure_->setToolTip(
        tr("Render the scene over a grid of settings against a reference, "
           "in the background"));
    cancel_ = new QAction(tr("&Cancel Measure"), this);
    cancel_->setObjectName(QStringLiteral("cancelMeasure"));
    connect(pin_, &QAction::triggered, this, &TradeoffView::pinCurrent);
    connect(unpin_, &QAction::triggered, this, &TradeoffView::unpinAll);
    connect(measure_, &QAction::triggered, this, &TradeoffView::confirmMeasure);
    connect(cancel_, &QAction::triggered, this, [this] {
        if (job_) job_->cancel();
        cancel_->setEnabled(false);
        progress_->setFormat(tr("Cancelling…"));
    });
}

void TradeoffView::buildWidgets() {
    pinStatus_ = makeStatus(QStringLiteral("pinStatus"));
    pinStale_ = makeStatus(QStringLiteral("pinStale"));
    // Hard to miss: every point from now on would be wrong.
    pinStale_->setStyleSheet(
        QStringLiteral("QLabel { background: #fff3c4; color: #5c4400; padding: 3px; }"));
    pinStale_->setText(
        tr("The pinned reference is out of date: the scene has changed since it was pinned. "
           "Renders are not scored against it until you pin again."));
    pinStale_->hide();
    measureStatus_ = makeStatus(QStringLiteral("measureStatus"));
    progress_ = new QProgressBar;
    progress_->setObjectName(QStringLiteral("measureProgress"));
    cancelButton_ = new QPushButton(tr("Cancel"));
    connect(cancelButton_, &QPushButton::clicked, cancel_, &QAction::trigger);
    plot_ = new PlotWidget;
    plot_->setObjectName(QStringLiteral("tradeoffPlot"));
    plotNote_ = makeStatus(QStringLiteral("plotNote"));
    pinnedTable_ = makePinnedTable();
    measureTable_ = makeMeasureTable();
    tabs_ = new QTabWidget;
    tabs_->addTab(pinnedTable_, tr("Pinned"));
    tabs_->addTab(measureTable_, tr("Measure"));
}

void TradeoffView::buildLayout() {
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(makeButton(pin_));
    buttons->addWidget(makeButton(unpin_));
    buttons->addStretch(1);
    buttons->addWidget(makeButton(measure_));
    auto* progressRow = new QHBoxLayout;
    progressRow->addWidget(progress_, 1);
    progressRow->addWidget(cancelButton_);
    plotBox_ = new QWidget;
    auto* plotLayout = new QVBoxLayout(plotBox_);
    plotLayout->setContentsMargins(0, 0, 0, 0);
    plotLayout->addWidget(plot_, 1);
    plotLayout->addWidget(plotNote_);
    split_ = new QSplitter;
    split_->setChildrenCollapsible(false);
    split_->addWidget(plotBox_);
    split_->addWidget(tabs_);
    connect(split_, &QSplitter::splitterMoved, this, [this] { splitMoved_ = true; });
    // Rows change the columns' widths: the split follows, once per burst.
    arrange_.setSingleShot(true);
    connect(&arrange_, &QTimer::timeout, this, &TradeoffView::arrangeSplit);
    for (QTableWidget* table : {pinnedTable_, measureTable_})
        connect(table->horizontalHeader(), &QHeaderView::sectionResized, &arrange_,
                qOverload<>(&QTimer::start));
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(buttons);
    layout->addWidget(pinStatus_);
    layout->addWidget(pinStale_);
    layout->addWidget(measureStatus_);
    layout->addLayout(progressRow);
    layout->addWidget(split_, 1);
}

void TradeoffView::connectUpdates() {
    liveRefresh_.setSingleShot(true);
    liveRefresh_.setInterval(kLiveRefreshMs);
    connect(&liveRefresh_, &QTimer::timeout, this, [this] {
        refreshPlot();
        fillMeasureTable(measureTable_, measurePoints());
    });
    connect(&errors_, &ErrorWorker::measured, this, &TradeoffView::onErrorMeasured);
    connect(doc_, &SceneDocument::sceneChanged, this, [this] {
        // A new render is on its way: what the view shows is no longer the
        // current settings' finished image.
        complete_.reset();
        // A converged reference of a scene that is gone would be stale at once.
        if (referenceJob_ && !sameSceneContent(doc_->scene(), referenceJob_->scene()))
            stopReference();
        updateActions();
        updatePinStatus();
        updateMeasureStatus();
    });
}

TradeoffView::~TradeoffView() {
    // Nothing may come back to a half-destroyed view.
    errors_.disconnect(this);
    // Not stopReference(): its status update reads the document, which the
    // main window may have destroyed already.
    if (referenceJob_) referenceJob_->disconnect(this);
    referenceJob_.reset();
    if (job_) job_->disconnect(this);
    job_.reset();
}

void TradeoffView::resizeEvent(QResizeEvent* e) {
    QWidget::resizeEvent(e);
    arrangeSplit();
}

void TradeoffView::arrangeSplit() {
    // Under the render view the dock is wide: plot and table side by side, the
    // table as wide as its columns need while the plot keeps a readable width.
    // Where both do not fit, the plot becomes a tab beside the tables, each
    // with the dock's whole width. In a side column, taller than wide, one
    // above the other. Stacked in a wide dock, plot and table would ask for
    // more height than the render view can spare.
    const bool tall = height() > width();
    const int tabFrame = tabs_->width() - tabs_->currentWidget()->width();
    const int tableWidth =
        std::max(tableContentWidth(pinnedTable_), tableContentWidth(measureTable_)) + tabFrame;
    const int room = width() - split_->handleWidth();
    setPlotTabbed(!tall && room - tableWidth < kMinPlotWidth);
    if (plotTabbed()) return;
    const auto orientation = tall ? Qt::Vertical : Qt::Horizontal;
    if (split_->orientation() == orientation && splitMoved_) return;
    split_->setOrientation(orientation);
    if (tall)
        split_->setSizes({height() * 7 / 10, height() - height() * 7 / 10});
    else
        split_->setSizes({room - tableWidth, tableWidth});
}

bool TradeoffView::plotTabbed() const {
    return tabs_->indexOf(plotBox_) >= 0;
}

void TradeoffView::setPlotTabbed(bool tabbed) {
    if (tabbed == plotTabbed()) return;
    if (tabbed) {
        tabs_->insertTab(0, plotBox_, tr("Plot"));
        tabs_->setCurrentWidget(plotBox_);
    } else {
        tabs_->removeTab(tabs_->indexOf(plotBox_));
        split_->insertWidget(0, plotBox_);
        plotBox_->show();
    }
}

void TradeoffView::showTable(QTableWidget* table) {
    // Tabbed, the plot is where new points show first.
    tabs_->setCurrentWidget(plotTabbed() ? plotBox_ : table);
}

void TradeoffView::sceneReplaced() {
    unpinAll();
    if (job_) {
        job_->disconnect(this);
        job_.reset();  // cancels and joins: the stop predicate answers within a tile row
        live_.clear();
        progress_->hide();
        cancelButton_->hide();
    }
    measureError_.clear();
    record_->clear();
    updateActions();
    updateMeasureStatus();
    refreshPlot();
    fillMeasureTable(measureTable_, measurePoints());
}

void TradeoffView::updateActions() {
    pin_->setEnabled(complete_.has_value());
    pin_->setText(complete_ ? tr("&Pin as Reference") : tr("&Pin as Reference (rendering…)"));
    unpin_->setEnabled(isPinned() || referenceJob_);
    measure_->setEnabled(!job_);
    cancel_->setEnabled(job_ != nullptr);
    progress_->setVisible(job_ != nullptr);
    cancelButton_->setVisible(job_ != nullptr);
}

void TradeoffView::refreshPlot() {
    std::vector<TradeoffPoint> shown = measurePoints();
    // While measuring, the front of the points so far.
    if (job_) markParetoFront(shown);
    const DockPlot plot = dockPlot(points_, shown);
    const bool empty = plot.spec.points.empty();
    plot_->setPlot(plot.spec, plot.tooltips);
    QString note;
    if (empty)
        note = tr("No points yet: pin a reference or measure.");
    else if (plot.identical > 0)
        // Not tr("%n point(s)"): with no translation loaded Qt keeps the "(s)".
        note = (plot.identical == 1 ? tr("1 point identical")
                                    : tr("%1 points identical").arg(plot.identical)) +
               tr(" to the reference: no error to show on a log axis.");
    plotNote_->setText(note);
    plotNote_->setVisible(!note.isEmpty());
}

}  // namespace whitted::ui
