#include "editor/export_job.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>

#include <algorithm>

#include "camera/camera_control.h"
#include "document/quality_choice.h"
#include "image/image_io.h"
#include "panels/image_size_fields.h"
#include "tracer/renderer.h"

namespace whitted::ui {

namespace {

QString firstExtension(const ImageFormatInfo& f) {
    return QString::fromLatin1(f.extensions.data(), int(f.extensions.size())).section(' ', 0, 0);
}

}  // namespace

namespace {

QSpinBox* spinBox(const char* name, int lo, int hi, int value) {
    auto* s = new QSpinBox;
    s->setObjectName(name);
    s->setRange(lo, hi);
    s->setValue(value);
    return s;
}

}  // namespace

ExportDialog::ExportDialog(const Scene& scene, const std::optional<QualityTarget>& quality,
                           const QString& directory, const QString& baseName, QWidget* parent)
    : QDialog(parent) {
    setWindowTitle(tr("Export Image"));
    auto* form = new QFormLayout(this);
    addFileRows(form, directory, baseName);
    addRenderRows(form, scene.render, quality);
    addTurntableRow(form);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Export"));
    form->addRow(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    emit path_->textChanged(path_->text());
}

// The file and its format; the format follows the name's extension, and the
// extension the format chosen.
void ExportDialog::addFileRows(QFormLayout* form, const QString& directory,
                               const QString& baseName) {
    path_ = new QLineEdit(QDir(directory).filePath(baseName + ".png"));
    path_->setObjectName("exportPath");
    path_->setMinimumWidth(360);
    auto* browse = new QPushButton(tr("Browse…"));
    auto* pathRow = new QHBoxLayout;
    pathRow->addWidget(path_);
    pathRow->addWidget(browse);
    form->addRow(tr("File"), pathRow);
    format_ = new QComboBox;
    format_->setObjectName("exportFormat");
    for (const ImageFormatInfo& f : imageFormats())
        format_->addItem(QString::fromLatin1(f.name.data(), int(f.name.size())) + " (" +
                         firstExtension(f) + ")");
    form->addRow(tr("Format"), format_);
    connect(browse, &QPushButton::clicked, this, &ExportDialog::browse);
    connect(format_, &QComboBox::activated, this, &ExportDialog::formatChosen);
    connect(path_, &QLineEdit::textChanged, this, [this](const QString& text) {
        const auto f = imageFormatFor(text.toStdString());
        if (!f) return;
        for (size_t i = 0; i < imageFormats().size(); ++i)
            if (imageFormats()[i].format == f->format) format_->setCurrentIndex(int(i));
    });
}

void ExportDialog::addRenderRows(QFormLayout* form, const RenderSettings& r,
                                 const std::optional<QualityTarget>& quality) {
    size_ = new ImageSizeFields(r.width, r.height, QStringLiteral("export"));
    samples_ = spinBox("exportSamples", 1, kMaxSamplesPerPixel, r.samplesPerPixel);
    depth_ = spinBox("exportDepth", 0, kMaxDepth, r.maxDepth);
    form->addRow(tr("Size"), size_);
    form->addRow(tr("Samples per pixel"), samples_);
    form->addRow(tr("Max depth"), depth_);
    precision_ = new QComboBox;
    precision_->setObjectName("exportPrecision");
    for (const auto& [value, name] : kPrecisionNames)
        precision_->addItem(QString::fromLatin1(name.data(), int(name.size())), int(value));
    precision_->setCurrentIndex(precision_->findData(int(r.precision)));
    form->addRow(tr("Precision"), precision_);
    quality_ = QualityChoice::makeComboBox(QStringLiteral("exportQuality"), quality);
    quality_->setToolTip(
        tr("With a target, the depth is chosen for the scene and each part of the picture "
           "is sampled until its estimated error is under the target"));
    form->addRow(tr("Render to"), quality_);
    // A target chooses the samples and the depth: their fields would say nothing.
    const auto followTarget = [this] {
        const bool settings = quality_->currentIndex() == 0;
        samples_->setEnabled(settings);
        depth_->setEnabled(settings);
    };
    connect(quality_, &QComboBox::currentIndexChanged, this, followTarget);
    followTarget();
}

void ExportDialog::addTurntableRow(QFormLayout* form) {
    turntable_ = spinBox("exportTurntable", 0, 9999, 0);
    turntable_->setSpecialValueText(tr("None: one image"));
    turntable_->setSuffix(tr(" frames"));
    turntable_->setToolTip(
        tr("Frames of a turntable: the eye turns once about the point it looks at, and each "
           "frame is written with its number before the extension (name.0001.png, …)."));
    form->addRow(tr("Turntable"), turntable_);
}

void ExportDialog::formatChosen(int index) {
    const QFileInfo info(path_->text());
    path_->setText(
        info.dir().filePath(info.completeBaseName() + firstExtension(imageFormats()[index])));
}

void ExportDialog::browse() {
    QStringList filters;
    for (const ImageFormatInfo& f : imageFormats()) {
        QStringList patterns;
        for (const QString& e : QString::fromLatin1(f.extensions.data(), int(f.extensions.size()))
                                    .split(' ', Qt::SkipEmptyParts))
            patterns << "*" + e;
        filters << QString::fromLatin1(f.name.data(), int(f.name.size())) + " (" +
                       patterns.join(' ') + ")";
    }
    const QString chosen =
        QFileDialog::getSaveFileName(this, tr("Export Image"), path_->text(), filters.join(";;"),
                                     &filters[format_->currentIndex()]);
    if (!chosen.isEmpty()) path_->setText(chosen);
}

ExportSettings ExportDialog::settings() const {
    ExportSettings s;
    s.path = path_->text();
    s.render.width = size_->imageWidth();
    s.render.height = size_->imageHeight();
    s.render.samplesPerPixel = samples_->value();
    s.render.maxDepth = depth_->value();
    s.render.precision = static_cast<Precision>(precision_->currentData().toInt());
    s.turntableFrames = turntable_->value();
    s.quality = QualityChoice::chosenIn(quality_);
    return s;
}

ExportJob::ExportJob(const Scene& scene, const ExportSettings& settings, PlanMemo& plans,
                     QObject* parent)
    : QObject(parent), scene_(scene), settings_(settings), plans_(plans) {
    scene_.render = settings.render;
}

ExportJob::~ExportJob() {
    cancelled_ = true;
    if (thread_.joinable()) thread_.join();
}

void ExportJob::start() {
    thread_ = std::thread([this] {
        const int frames = settings_.turntableFrames;
        const Camera camera = scene_.camera;  // the turntable's frames turn about it
        double seconds = 0.0;
        for (int frame = frames > 0 ? 1 : 0; frame <= frames; ++frame)
            if (!exportFrame(frame, camera, seconds)) return;
        if (frames == 0)
            emit finished(true, tr("Exported %1 in %2 s.%3")
                                    .arg(settings_.path)
                                    .arg(seconds, 0, 'f', 2)
                                    .arg(reached_));
        else
            emit finished(true, tr("Exported %1 frames, %2 to %3, in %4 s.")
                                    .arg(frames)
                                    .arg(QString::fromStdString(
                                        frameFile(settings_.path.toStdString(), 1).string()))
                                    .arg(QString::fromStdString(
                                        frameFile(settings_.path.toStdString(), frames).string()))
                                    .arg(seconds, 0, 'f', 2));
    });
}

bool ExportJob::exportFrame(int frame, const Camera& camera, double& seconds) {
    const int frames = std::max(1, settings_.turntableFrames);
    if (frame > 0) scene_.camera = turntableCamera(camera, frame, frames);
    RenderOptions options = oneShotOptions();
    Scene scene = scene_;
    const StopPredicate cancelled = [this] { return cancelled_.load(); };
    std::shared_ptr<const QualityPlan> plan;
    if (settings_.quality) {
        plan = plans_.plan(scene, *settings_.quality, kDefaultMaxSamples, cancelled);
        if (plan->stopped) {  // cancelled while planning: the plan means nothing
            emit finished(false, tr("Export cancelled."));
            return false;
        }
        applyPlan(*plan, scene, options);
    }
    std::atomic<int> lastPercent{-1};  // tiles report from several threads
    const RenderResult result = render(
        scene, options,
        [&](const TileUpdate& t) {
            const double done = (std::max(frame, 1) - 1 + t.progress.fraction) / frames;
            const int percent = static_cast<int>(done * 100);
            if (lastPercent.exchange(percent) != percent) emit progress(percent);
        },
        cancelled);
    if (!result.completed) {
        emit finished(false, tr("Export cancelled."));
        return false;
    }
    try {
        writeImage(result.image, frameFile(settings_.path.toStdString(), frame),
                   plan && result.adaptive
                       ? qualityMetadata(scene, *plan, *result.adaptive, result.seconds, "whitted")
                       : makeImageMetadata(scene.render, result.seconds, "whitted"));
    } catch (const std::exception& e) {
        emit finished(false, QString::fromStdString(e.what()));
        return false;
    }
    seconds += result.seconds;
    if (plan && result.adaptive) reached_ = qualityReached(*plan, *result.adaptive);
    return true;
}

QString ExportJob::qualityReached(const QualityPlan& plan, const AdaptiveOutcome& reached) const {
    QString text = tr(" %1: %2").arg(QualityChoice::describe(plan.target),
                                     QualityChoice::reachedText(plan, reached));
    if (plan.target.largestCodes)
        text += tr(", largest error about %1 codes")
                    .arg(std::max(plan.depthLargest, reached.estimatedLargest), 0, 'f', 1);
    return text + ".";
}

}  // namespace whitted::ui
