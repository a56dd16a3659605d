#include "tradeoff_dock/tradeoff_view.h"

#include <QAction>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QResizeEvent>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cstdlib>

#include "document/scene_document.h"
#include "plot/plot_widget.h"
#include "tradeoff_dock/settings_prediction.h"
#include "tradeoff_dock/tradeoff_plot_spec.h"
#include "tradeoff_dock/tradeoff_record.h"
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

// Whether `image` is `reference` or a reduction of it at the same aspect ratio
// (a render at a lower resolution scale), which measureError compares stretched.
bool comparable(const Image& image, const Image& reference) {
    const long long w = image.width, h = image.height;
    const long long W = reference.width, H = reference.height;
    return w <= W && h <= H && std::llabs(w * H - W * h) <= std::max(W, H);
}

QString sizeText(int w, int h) {
    return QObject::tr("%1 × %2").arg(w).arg(h);
}

}  // namespace

TradeoffView::TradeoffView(SceneDocument* doc, TradeoffRecord* record, QWidget* parent)
    : QWidget(parent),
      doc_(doc),
      record_(record),
      grid_(editorMeasureGrid()),
      referenceSamples_(kEditorReferenceSamples) {
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
    updateActions();
    updatePinStatus();
    updateMeasureStatus();
    refreshPlot();
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

void TradeoffView::setMeasureGrid(const TradeoffGrid& grid, int referenceSamples) {
    grid_ = grid;
    referenceSamples_ = referenceSamples;
}

const std::vector<TradeoffPoint>& TradeoffView::measurePoints() const {
    static const std::vector<TradeoffPoint> none;
    if (job_) return live_;
    const MeasureResults* m = record_->measure();
    return m ? m->points : none;
}

bool TradeoffView::isPinStale() const {
    return isPinned() && !sameSceneContent(doc_->scene(), pinnedScene_);
}

void TradeoffView::frameShown(const RenderFrame& frame) {
    if (!frame.renderComplete || !frame.linear) return;
    complete_ = frame;
    updateActions();
    if (frame.generation > pinnedGeneration_) scoreFrame(frame);
}

void TradeoffView::scoreFrame(const RenderFrame& frame) {
    // A frame always shows the document's scene (MainWindow drops older ones).
    if (!pinnedImage_ || isPinStale()) return;
    PinnedPoint p;
    p.id = nextId_++;
    p.generation = frame.generation;
    p.settings = frame.settings;
    p.seconds = frame.seconds;
    p.rays = frame.rays;
    const bool fits = comparable(*frame.linear, *pinnedImage_);
    if (fits)
        errors_.submit({p.id, frame.linear, pinnedImage_});
    else
        p.note = tr("Not compared: %1 is neither the pinned %2 nor a reduction of it")
                     .arg(sizeText(frame.linear->width, frame.linear->height),
                          sizeText(pinnedImage_->width, pinnedImage_->height));
    points_.push_back(p);
    fillPinnedTable(pinnedTable_, points_);
    if (!fits) emit pointMeasured(p);
}

void TradeoffView::onErrorMeasured(quint64 id, const ErrorStats& error) {
    // Points of an earlier pin are gone; their ids are never reused.
    const auto p = std::find_if(points_.begin(), points_.end(),
                                [id](const PinnedPoint& q) { return q.id == id; });
    if (p == points_.end()) return;
    p->error = error;
    fillPinnedTable(pinnedTable_, points_);
    refreshPlot();
    emit pointMeasured(*p);
}

void TradeoffView::pinCurrent() {
    if (!complete_) return;  // the action is disabled then; a shortcut may still race
    if (complete_->settings.samplesPerPixel < kNoisyBelowSamples) {
        offerConvergedReference(*complete_);
        return;
    }
    pin(complete_->linear, complete_->settings, complete_->seconds, complete_->generation,
        doc_->scene());
}

void TradeoffView::offerConvergedReference(const RenderFrame& noisy) {
    const int spp = noisy.settings.samplesPerPixel;
    const QString text =
        tr("This image has only %1 per pixel: its edges are still jagged, and every later "
           "render would be scored against that noise instead of the true picture.\n\n"
           "Render a converged reference at %2 samples per pixel (in double precision, in the "
           "background) and pin it when it is done?")
            .arg(spp == 1 ? tr("1 sample") : tr("%1 samples").arg(spp))
            .arg(referenceSamples_);
    auto* box = new QMessageBox(QMessageBox::Warning, tr("Pin a Noisy Image?"), text,
                                QMessageBox::Cancel, this);
    box->setObjectName(QStringLiteral("noisyPinWarning"));
    QPushButton* converged =
        box->addButton(tr("Render Converged Reference"), QMessageBox::AcceptRole);
    converged->setObjectName(QStringLiteral("renderConvergedButton"));
    QPushButton* anyway = box->addButton(tr("Pin This Image Anyway"), QMessageBox::ActionRole);
    anyway->setObjectName(QStringLiteral("pinAnywayButton"));
    box->setDefaultButton(converged);
    box->setAttribute(Qt::WA_DeleteOnClose);
    // The frame as it was when asked: the view may have moved on by the answer.
    const Scene scene = doc_->scene();
    connect(converged, &QPushButton::clicked, this, &TradeoffView::startConvergedReference);
    connect(anyway, &QPushButton::clicked, this, [this, noisy, scene] {
        pin(noisy.linear, noisy.settings, noisy.seconds, noisy.generation, scene);
    });
    // Not exec(): the editor (and a test driving it) carries on while it is open.
    box->open();
}

void TradeoffView::startConvergedReference() {
    stopReference();
    referenceError_.clear();
    // At the size the view renders, so that its frames compare with it.
    referenceJob_ = std::make_unique<ReferenceJob>(viewSized(doc_->scene()), referenceSamples_);
    connect(referenceJob_.get(), &ReferenceJob::finished, this, &TradeoffView::onReferenceRendered);
    referenceJob_->start();
    updateActions();
    updatePinStatus();
}

void TradeoffView::stopReference() {
    if (!referenceJob_) return;
    referenceJob_->disconnect(this);
    referenceJob_.reset();  // cancels and joins: the stop is asked every tile row
    updateActions();
    updatePinStatus();
}

void TradeoffView::onReferenceRendered(const ConvergedReference& reference, const QString& error) {
    if (!referenceJob_ || sender() != referenceJob_.get()) return;
    const Scene scene = referenceJob_->scene();
    referenceJob_.reset();  // its thread has returned from run(): the join is immediate
    referenceError_ = error;
    if (!error.isEmpty() || !reference.image) {
        updateActions();
        updatePinStatus();
        return;
    }
    // Every frame from now on is scored; the one on screen at once.
    pin(reference.image, reference.settings, reference.seconds,
        complete_ ? complete_->generation : 0, scene);
    if (complete_) scoreFrame(*complete_);
}

void TradeoffView::pin(std::shared_ptr<const Image> image, const RenderSettings& settings,
                       double seconds, quint64 generation, const Scene& scene) {
    stopReference();
    errors_.clear();
    points_.clear();
    pinnedImage_ = std::move(image);
    pinnedSettings_ = settings;
    pinnedSeconds_ = seconds;
    pinnedGeneration_ = generation;
    pinnedScene_ = scene;
    fillPinnedTable(pinnedTable_, points_);
    showTable(pinnedTable_);
    updateActions();
    updatePinStatus();
    refreshPlot();
}

void TradeoffView::unpinAll() {
    stopReference();
    referenceError_.clear();
    errors_.clear();
    points_.clear();
    pinnedImage_.reset();
    fillPinnedTable(pinnedTable_, points_);
    updateActions();
    updatePinStatus();
    refreshPlot();
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

void TradeoffView::confirmMeasure() {
    if (job_) return;
    const Scene& scene = doc_->scene();
    const auto& g = grid_;
    const QString text =
        tr("Measure renders this scene at %1 settings: %2 to %3 samples per pixel, depth %4 to "
           "%5, float and double, at %6 of %7. Each is timed and compared with a reference "
           "rendered in double at %8 samples per pixel.\n\n"
           "The seed scene at 640 × 480 takes about a minute on two free cores, up to two "
           "minutes on a busy machine; mirrors, glass and more pixels take longer. The editor "
           "keeps working meanwhile, and Cancel keeps the points measured so far.")
            .arg(gridPointCount(g))
            .arg(*std::min_element(g.samples.begin(), g.samples.end()))
            .arg(*std::max_element(g.samples.begin(), g.samples.end()))
            .arg(*std::min_element(g.depths.begin(), g.depths.end()))
            .arg(*std::max_element(g.depths.begin(), g.depths.end()))
            .arg([&] {
                QStringList s;
                for (double scale : g.scales) s << QStringLiteral("%1 %").arg(scale * 100);
                return s.join(tr(" and "));
            }())
            .arg(sizeText(scene.render.width, scene.render.height))
            .arg(referenceSamples_);
    auto* box = new QMessageBox(QMessageBox::Question, tr("Measure Trade-off"), text,
                                QMessageBox::Cancel, this);
    box->setObjectName(QStringLiteral("measureConfirm"));
    box->setDefaultButton(box->addButton(tr("Measure"), QMessageBox::AcceptRole));
    box->setAttribute(Qt::WA_DeleteOnClose);
    connect(box, &QMessageBox::accepted, this, &TradeoffView::startMeasure);
    // Not exec(): the editor (and a test driving it) carries on while it is open.
    box->open();
}

bool TradeoffView::startMeasure() {
    if (job_) return false;
    live_.clear();
    measureError_.clear();
    job_ = std::make_unique<MeasureJob>(doc_->scene(), grid_, referenceSamples_);
    connect(job_.get(), &MeasureJob::referenceDone, this, [this](double seconds) {
        if (!job_) return;
        progress_->setRange(0, job_->total());
        progress_->setValue(0);
        progress_->setFormat(tr("Reference in %1; %v of %m points").arg(secondsText(seconds)));
    });
    connect(job_.get(), &MeasureJob::pointMeasured, this, &TradeoffView::onMeasurePoint);
    connect(job_.get(), &MeasureJob::finished, this, &TradeoffView::onMeasureFinished);
    progress_->setRange(0, 0);  // busy until the reference is done
    progress_->setFormat(tr("Rendering the reference…"));
    progress_->show();
    cancelButton_->show();
    job_->start();
    showTable(measureTable_);
    updateActions();
    updateMeasureStatus();
    refreshPlot();
    fillMeasureTable(measureTable_, live_);
    return true;
}

void TradeoffView::onMeasurePoint(const TradeoffPoint& point, int done, int total) {
    // A job dropped by sceneReplaced() may have posted more before it stopped.
    if (!job_ || sender() != job_.get()) return;
    live_.push_back(point);
    progress_->setRange(0, total);
    progress_->setValue(done);
    if (!liveRefresh_.isActive()) liveRefresh_.start();
    emit measureProgress(done, total);
}

void TradeoffView::onMeasureFinished(const MeasureResults& results, const QString& error) {
    if (!job_ || sender() != job_.get()) return;
    job_.reset();  // its thread has returned from run(): the join is immediate
    live_.clear();
    liveRefresh_.stop();
    measureError_ = error;
    // A run stopped before its first point would only throw away the last one's.
    if (!results.points.empty()) record_->setMeasure(results);
    progress_->hide();
    cancelButton_->hide();
    updateActions();
    updateMeasureStatus();
    refreshPlot();
    fillMeasureTable(measureTable_, measurePoints());
    emit measureFinished(results.cancelled);
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

void TradeoffView::updatePinStatus() {
    pinStale_->setVisible(isPinStale());
    if (referenceJob_) {
        pinStatus_->setText(tr("Rendering a converged reference at %1 samples per pixel in the "
                               "background; it is pinned when done (Unpin cancels).")
                                .arg(referenceJob_->samples()));
        return;
    }
    if (!referenceError_.isEmpty()) {
        pinStatus_->setText(tr("The converged reference failed: %1").arg(referenceError_));
        return;
    }
    if (!isPinned()) {
        pinStatus_->setText(
            tr("Pin the finished image as a reference to plot every later "
               "render's error against it."));
        return;
    }
    const RenderSettings& s = pinnedSettings_;
    pinStatus_->setText(tr("Pinned: %1, %2, rendered in %3. Every finished render adds a point.")
                            .arg(settingsText(s.samplesPerPixel, s.maxDepth, s.precision),
                                 sizeText(s.width, s.height), secondsText(pinnedSeconds_)));
}

void TradeoffView::updateMeasureStatus() {
    if (job_) {
        measureStatus_->setText(
            tr("Measuring %1 settings of the scene at %2…")
                .arg(job_->total())
                .arg(sizeText(doc_->scene().render.width, doc_->scene().render.height)));
        return;
    }
    QString text;
    const MeasureResults* m = record_->measure();
    if (m) {
        const auto front = std::count_if(m->points.begin(), m->points.end(),
                                         [](const TradeoffPoint& p) { return p.pareto; });
        text = tr("Measure: %1 of %2 points in %3, %4 on the Pareto front; reference %5 spp, "
                  "depth %6, double (%7).")
                   .arg(m->points.size())
                   .arg(m->total)
                   .arg(secondsText(m->seconds))
                   .arg(front)
                   .arg(m->referenceSamples)
                   .arg(m->referenceDepth)
                   .arg(secondsText(m->referenceSeconds));
        if (m->cancelled) text += QLatin1Char(' ') + tr("Cancelled: the rest was not measured.");
        if (!sameSceneContent(doc_->scene(), m->scene))
            text += QLatin1Char(' ') +
                    tr("The scene has changed since: the Render tab no longer predicts from it.");
    } else {
        text =
            tr("Measure renders the scene over a grid of settings, against a reference, in "
               "the background.");
    }
    if (!measureError_.isEmpty()) text = tr("Measure failed: %1").arg(measureError_) + ' ' + text;
    measureStatus_->setText(text);
}

void TradeoffView::refreshPlot() {
    std::vector<TradeoffPoint> shown = measurePoints();
    // While measuring, the front of the points so far.
    if (job_) markParetoFront(shown);
    const TradeoffPlot plot = tradeoffPlot(points_, shown);
    const bool empty = plot.spec.points.empty();
    plot_->setPlot(plot.spec, plot.tooltips);
    QString note;
    if (empty)
        note = tr("No points yet: pin a reference or measure.");
    else if (plot.identical > 0)
        note = tr("%n point(s) identical to the reference: no error to show on a log axis.",
                  nullptr, plot.identical);
    plotNote_->setText(note);
    plotNote_->setVisible(!note.isEmpty());
}

}  // namespace whitted::ui
