// TradeoffView's Measure: asking first, running a MeasureJob with progress and
// Cancel, showing its points as they come, and the last run's summary.
#include "tradeoff_dock/tradeoff_view.h"

#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>

#include <algorithm>

#include "document/scene_document.h"
#include "document/settings_words.h"
#include "prediction/render_record.h"
#include "prediction/settings_prediction.h"
#include "tradeoff_dock/tradeoff_tables.h"

namespace whitted::ui {

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

}  // namespace whitted::ui
