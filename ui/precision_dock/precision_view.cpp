#include "precision_dock/precision_view.h"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QScrollArea>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

#include "document/scene_document.h"
#include "image/heat_map.h"
#include "precision_dock/heat_map_view.h"

namespace whitted::ui {

namespace {

// "0.016 % (3 px)": the share first, as the contract states its bounds in shares.
QString pixelsText(std::size_t n, std::size_t total) {
    const double percent = total ? 100.0 * double(n) / double(total) : 0.0;
    const QString share = n > 0 && percent < 0.001 ? QStringLiteral("< 0.001")
                                                   : QString::number(percent, 'f', n == 0 ? 0 : 3);
    return QObject::tr("%1 % (%2 px)").arg(share).arg(n);
}

// The ramp from identical (black) to 8/255 and more, with its scale under it.
QWidget* makeLegend() {
    QImage ramp(256, 1, QImage::Format_RGB32);
    for (int x = 0; x < 256; ++x) {
        const glm::vec3 c = heatMapColour(kHeatMapSaturation * float(x) / 255.0f);
        ramp.setPixel(x, 0,
                      qRgb(int(std::lround(c.r * 255)), int(std::lround(c.g * 255)),
                           int(std::lround(c.b * 255))));
    }
    auto* bar = new QLabel;
    bar->setPixmap(QPixmap::fromImage(ramp));
    bar->setScaledContents(true);
    bar->setFixedHeight(10);
    bar->setToolTip(QObject::tr("Largest channel difference of the 8-bit display values"));

    auto* scale = new QHBoxLayout;
    scale->setContentsMargins(0, 0, 0, 0);
    scale->addWidget(new QLabel(QObject::tr("identical")), 1, Qt::AlignLeft);
    scale->addWidget(new QLabel(QObject::tr("4/255")), 1, Qt::AlignHCenter);
    scale->addWidget(new QLabel(QObject::tr("8/255 or more")), 1, Qt::AlignRight);

    auto* legend = new QWidget;
    auto* layout = new QVBoxLayout(legend);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(bar);
    layout->addLayout(scale);
    return legend;
}

QLabel* makeValue(const QString& name, const QString& tip) {
    auto* label = new QLabel;
    label->setObjectName(name);
    label->setToolTip(tip);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

// In a short dock a scroll bar, rather than text squeezed into illegible lines.
void putInScrollArea(QWidget* view, QWidget* content) {
    auto* scroll = new QScrollArea;
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setWidget(content);
    auto* outer = new QVBoxLayout(view);
    outer->setContentsMargins(0, 0, 0, 0);
    outer->addWidget(scroll);
}

}  // namespace

QSize PrecisionView::comparisonSize(const Scene& scene) {
    const int w = scene.render.width, h = scene.render.height;
    if (std::max(w, h) <= kMaxSide) return {w, h};
    if (w >= h) return {kMaxSide, std::max(1, int(std::lround(double(h) * kMaxSide / w)))};
    return {std::max(1, int(std::lround(double(w) * kMaxSide / h))), kMaxSide};
}

PrecisionView::PrecisionView(SceneDocument* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
    // For someone who has never heard of float and double: what is compared, and why look.
    intro_ = new QLabel(
        tr("Renders the scene with 32-bit (float) and 64-bit (double) numbers and shows where "
           "the two pictures differ: where they barely do, the faster float is accurate enough."));
    intro_->setObjectName(QStringLiteral("precisionIntro"));
    intro_->setWordWrap(true);
    status_ = new QLabel;
    status_->setObjectName(QStringLiteral("precisionStatus"));
    status_->setWordWrap(true);
    heatMap_ = new HeatMapView;
    heatMap_->setObjectName(QStringLiteral("precisionHeatMap"));
    heatMap_->setToolTip(tr("Where the float render differs from the double render"));

    over1_ = makeValue(QStringLiteral("precisionOver1"),
                       tr("Pixels whose float and double display values differ by more than "
                          "one 8-bit step"));
    over2_ = makeValue(QStringLiteral("precisionOver2"),
                       tr("Pixels that differ by more than two 8-bit steps (the contract "
                          "allows 0.1 % for the seed scene)"));
    largest_ = makeValue(QStringLiteral("precisionLargest"),
                         tr("The largest difference of any pixel, in 8-bit steps"));
    const QString decision =
        tr("Pixels whose camera ray tree (through the pixel centre) first differs in %1");
    hit_ = makeValue(QStringLiteral("precisionHit"), decision.arg(tr("which sphere a ray hits")));
    shadow_ = makeValue(QStringLiteral("precisionShadow"),
                        decision.arg(tr("whether a light is shadowed")));
    tir_ = makeValue(QStringLiteral("precisionTir"),
                     decision.arg(tr("whether total internal reflection happens")));

    auto* form = new QFormLayout;
    form->addRow(tr("Pixels over 1/255:"), over1_);
    form->addRow(tr("Pixels over 2/255:"), over2_);
    form->addRow(tr("Largest difference:"), largest_);
    form->addRow(tr("Different hit:"), hit_);
    form->addRow(tr("Different shadow:"), shadow_);
    form->addRow(tr("Different total internal reflection:"), tir_);

    auto* content = new QWidget;
    auto* layout = new QVBoxLayout(content);
    layout->addWidget(intro_);
    layout->addWidget(status_);
    layout->addWidget(heatMap_, 1);
    layout->addWidget(makeLegend());
    layout->addLayout(form);
    putInScrollArea(this, content);

    debounce_.setSingleShot(true);
    connect(&debounce_, &QTimer::timeout, this, &PrecisionView::startWhenMainRenderDone);
    connect(doc_, &SceneDocument::sceneChanged, this, &PrecisionView::sceneChanged);
    connect(&worker_, &PrecisionWorker::comparisonReady, this, &PrecisionView::onResult);
    status_->setText(tr("Compares once the dock is shown."));
}

void PrecisionView::mainFrameShown(const RenderFrame& frame) {
    mainRenderRunning_ = !frame.renderComplete;
    if (mainRenderRunning_ || !waitingForMain_) return;
    waitingForMain_ = false;
    // Not from inside the frame's signal: every other receiver sees the frame first.
    debounce_.start(0);
}

void PrecisionView::sceneChanged() {
    dirty_ = true;
    // Every edit restarts the main render (MainWindow), whose frames say when it is done.
    mainRenderRunning_ = true;
    if (!isVisible()) return;
    // The running comparison is of an old scene: stop it now, start again once edits pause.
    worker_.cancel();
    inFlight_ = false;
    waitingForMain_ = false;  // the quiet time comes first, then the wait
    debounce_.start(kDebounceMs);
    status_->setText(tr("Scene changed: comparing again shortly…"));
}

void PrecisionView::showEvent(QShowEvent* e) {
    QWidget::showEvent(e);
    if (dirty_ && !inFlight_ && !waitingForMain_) debounce_.start(0);
}

void PrecisionView::hideEvent(QHideEvent* e) {
    QWidget::hideEvent(e);
    // Nobody looks: no work. What was pending is done again when shown.
    if (debounce_.isActive() || inFlight_ || waitingForMain_) dirty_ = true;
    debounce_.stop();
    waitingForMain_ = false;
    worker_.cancel();
    inFlight_ = false;
}

void PrecisionView::startWhenMainRenderDone() {
    if (!mainRenderRunning_) {
        start();
        return;
    }
    // Both at once would share the cores and delay the picture the user is editing.
    waitingForMain_ = true;
    status_->setText(tr("Waiting for the main render to finish…"));
}

void PrecisionView::start() {
    const Scene& scene = doc_->scene();
    const QSize size = comparisonSize(scene);
    dirty_ = false;
    inFlight_ = true;
    const quint64 generation = worker_.request(scene, size);
    status_->setText(
        tr("Comparing float and double at %1 × %2…").arg(size.width()).arg(size.height()));
    emit comparisonStarted(generation);
}

void PrecisionView::onResult(const PrecisionResult& result) {
    if (result.generation != worker_.latestGeneration()) return;  // stale
    inFlight_ = false;
    shown_ = result;
    const PrecisionComparison& c = result.comparison;
    heatMap_->setImage(result.heatMap);
    over1_->setText(pixelsText(c.over1, c.pixels));
    over2_->setText(pixelsText(c.over2, c.pixels));
    largest_->setText(tr("%1 steps of 1/255").arg(double(c.largest) * 255.0, 0, 'f', 1));
    hit_->setText(pixelsText(c.hitDiffers, c.pixels));
    shadow_->setText(pixelsText(c.shadowDiffers, c.pixels));
    tir_->setText(pixelsText(c.tirDiffers, c.pixels));
    const RenderSettings& render = doc_->scene().render;
    const QString size =
        render.width == c.width && render.height == c.height
            ? tr("the scene's full size")
            : tr("preview size; the scene renders at %1 × %2").arg(render.width).arg(render.height);
    const int spp = render.samplesPerPixel;
    status_->setText(tr("Measured at %1 × %2 (%3), %4 per pixel, in %5 s.")
                         .arg(c.width)
                         .arg(c.height)
                         .arg(size)
                         .arg(spp == 1 ? tr("1 sample") : tr("%1 samples").arg(spp))
                         .arg(result.seconds, 0, 'f', 2));
    emit comparisonShown(result);
}

}  // namespace whitted::ui
