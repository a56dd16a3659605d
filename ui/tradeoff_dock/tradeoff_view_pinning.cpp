// TradeoffView's pin: pinning the finished image (or a converged reference
// rendered for it), scoring every later render against it, unpinning.
#include "tradeoff_dock/tradeoff_view.h"

#include <QLabel>
#include <QMessageBox>
#include <QPushButton>

#include <algorithm>
#include <cstdlib>

#include "document/scene_document.h"
#include "document/settings_words.h"
#include "prediction/settings_prediction.h"
#include "tradeoff_dock/tradeoff_tables.h"

namespace whitted::ui {

namespace {

// Whether `image` is `reference` or a reduction of it at the same aspect ratio
// (a render at a lower resolution scale), which measureError compares stretched.
bool comparable(const Image& image, const Image& reference) {
    const long long w = image.width, h = image.height;
    const long long W = reference.width, H = reference.height;
    return w <= W && h <= H && std::llabs(w * H - W * h) <= std::max(W, H);
}

}  // namespace

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

}  // namespace whitted::ui
