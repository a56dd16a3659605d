#include "editor/main_window.h"

#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QGuiApplication>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressDialog>
#include <QPushButton>
#include <QScopedValueRollback>
#include <QScreen>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>

#include <utility>

#include "document/autosave.h"
#include "document/scene_loading.h"
#include "editor/export_job.h"
#include "editor/float_range_warning.h"
#include "editor/window_placement.h"
#include "image/heat_map.h"
#include "image/image_error.h"
#include "panels/preset_controls.h"
#include "panels/scene_panel.h"
#include "tradeoff_dock/tradeoff_view.h"
#include "viewport/image_convert.h"
#include "viewport/render_view.h"

namespace whitted::ui {

namespace {
constexpr int kMaxRecentFiles = 8;
const char* kSceneFilter = "Whitted scenes (*.json);;All files (*)";

// A scene's file name for the user, or `untitled` for a scene never saved.
QString sceneName(const QString& path, const QString& untitled) {
    return path.isEmpty() ? untitled : QFileInfo(path).fileName();
}
}  // namespace

Scene MainWindow::newSceneTemplate() {
    Scene s;
    s.camera = Camera{{0, 1, -4}, {0, 0.4, 0}, {0, 1, 0}, 50};
    s.background = {0.02, 0.02, 0.03};
    s.render.maxDepth = 3;
    s.materials = {
        Material{"red", {0.8, 0.1, 0.1}, 0.6, 60, 0.2, 0, 1.5, std::nullopt},
        Material{"floor", {0.8, 0.8, 0.8}, 0.2, 50, 0.1, 0, 1.5, Checker{{0.1, 0.1, 0.1}, 0.5}}};
    s.lights = {Light{"key", {3, 5, -4}, {1, 1, 1}, 1}};
    s.spheres = {Sphere{"ball", {0, 0.5, 0}, 0.5, "red"},
                 Sphere{"floor", {0, -99999.5, 0}, 99999, "floor"}};
    return s;
}

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setAcceptDrops(true);
    connectRendersAndPredictions();
    view_ = new RenderView(&doc_, this);
    setCentralWidget(view_);
    buildDocks();
    buildMenus();
    addFieldToolTips(this);
    buildStatusBar();
    connect(&doc_, &SceneDocument::modifiedChanged, this, &MainWindow::updateTitle);
    connect(&doc_, &SceneDocument::filePathChanged, this, &MainWindow::updateTitle);
    connect(&worker_, &RenderWorker::frameReady, this, &MainWindow::onFrame);
    connect(view_, &RenderView::moveMessage, this, [this](const QString& text) {
        if (text.isEmpty())
            statusBar()->clearMessage();
        else
            statusBar()->showMessage(text);
    });
    restorePlacement();
    rebuildRecentMenu();
    doc_.reset(newSceneTemplate(), QString());
    view_->setHomeCamera(doc_.scene().camera);
    updateTitle();
}

void MainWindow::connectRendersAndPredictions() {
    // The first to hear of a change, so that the render starts while the
    // panels and the rest refresh (a few ms on a scene of 100,000 spheres).
    // The request waiting would hold the scene the edit writes: sceneChanged
    // brings a new one.
    connect(&doc_, &SceneDocument::aboutToWrite, this, [this] { worker_.dropWaiting(); });
    connect(&doc_, &SceneDocument::sceneChanged, this, &MainWindow::requestRender);
    connect(&quality_, &QualityChoice::changed, this, &MainWindow::requestRender);
    // Predicted once the scene rests: a move with the pointer changes it at
    // every event, and each prediction took a core from the render.
    predictPause_.setSingleShot(true);
    predictPause_.setInterval(kPredictPauseMs);
    connect(&predictPause_, &QTimer::timeout, this, [this] {
        predictionDue_ = true;
        predictWhenShown();
    });
    const auto predict = [this] { predictPause_.start(); };
    connect(&doc_, &SceneDocument::sceneChanged, this, predict);
    connect(&quality_, &QualityChoice::changed, this, predict);
    // Before the Render tab refreshes: the renders' times are of the old content.
    connect(&doc_, &SceneDocument::sceneChanged, this, [this] {
        if (std::exchange(renderedRevision_, doc_.contentRevision()) != doc_.contentRevision())
            record_.contentChanged();
    });
    connect(&predictor_, &ProbePredictor::predicted, &record_, &RenderRecord::setProbePrediction);
}

// The render's figures, the recovery copy's failures and the float range
// warning.
void MainWindow::buildStatusBar() {
    passLabel_ = new QLabel;
    samplesLabel_ = new QLabel;
    timeLabel_ = new QLabel;
    speedLabel_ = new QLabel;
    for (QLabel* l : {passLabel_, samplesLabel_, timeLabel_, speedLabel_})
        statusBar()->addPermanentWidget(l);
    autosave_ = std::make_unique<Autosave>(&doc_);
    connect(autosave_.get(), &Autosave::written, this, [this](const QString& error) {
        if (!error.isEmpty())
            statusBar()->showMessage(tr("Could not write the recovery copy: %1").arg(error), 10000);
    });
    floatRangeWarning_ = new FloatRangeWarning(&doc_, {}, statusBar());
    statusBar()->addWidget(floatRangeWarning_);
}

// Where the window and its docks were; on a first start, or where no screen
// shows that place any more, a size that leaves room for the view.
void MainWindow::restorePlacement() {
    QSettings settings;
    if (!restoreGeometry(settings.value("window/geometry").toByteArray()) ||
        !someScreenShows(geometry())) {
        // First start: room for the view, the docks only as wide as their forms.
        const QRect available = screen()->availableGeometry();
        resize(firstWindowSize(available.size()));
        move(available.center() - rect().center());
        // Once shown: before that the docks have no width to give away.
        QTimer::singleShot(0, this, [this] {
            resizeDocks(
                {findChild<QDockWidget*>("sceneDock"), findChild<QDockWidget*>("settingsDock")},
                {230, 340}, Qt::Horizontal);
        });
    }
    restoreState(settings.value("window/state").toByteArray());
}

MainWindow::~MainWindow() = default;

void MainWindow::sceneReplaced() {
    view_->setHomeCamera(doc_.scene().camera);
    // Times, errors and the pinned image belong to the scene that was open.
    tradeoffView_->sceneReplaced();
    quality_.forgetReached();
}

void MainWindow::requestRender() {
    worker_.request(doc_.snapshot(), quality_.target(), quality_.whitted1980(),
                    doc_.geometryRevision());
    newestFrameShown_ = false;
}

void MainWindow::predictWhenShown() {
    if (!predictionDue_ || !newestFrameShown_) return;
    predictionDue_ = false;
    predictor_.sceneChanged(doc_.scene(), quality_.target(), doc_.contentRevision());
}

void MainWindow::onFrame(const RenderFrame& frame) {
    // Stale: a newer request exists, and its frames must not be overwritten.
    if (frame.generation != worker_.latestGeneration()) return;
    newestFrameShown_ = true;
    // Queued behind the paint that setFrame() asks for, so that the frame is
    // on screen before the prediction copies the scene.
    QMetaObject::invokeMethod(this, &MainWindow::predictWhenShown, Qt::QueuedConnection);
    lastFrame_ = frame;
    showFrameOrMap();
    // A render to a quality decides after each pass whether another follows:
    // it has no count of passes to give.
    passLabel_->setText(frame.preview ? tr("Preview")
                        : frame.qualityPlan
                            ? tr("Pass %1").arg(frame.pass + 1)
                            : tr("Pass %1 of %2").arg(frame.pass + 1).arg(frame.passCount));
    samplesLabel_->setText(!frame.whitted1980 ? QualityChoice::samplesPerPixel(frame.samples)
                           : frame.renderComplete
                               ? tr("Whitted 1980: %1 camera rays a pixel")
                                     .arg(double(frame.cameraRays) / (double(frame.settings.width) *
                                                                      frame.settings.height),
                                          0, 'f', 2)
                               : tr("Whitted 1980 sampling"));
    timeLabel_->setText(tr("%1 s").arg(frame.seconds, 0, 'f', 2));
    speedLabel_->setText(frame.renderComplete
                             ? tr("%1 Mrays/s").arg(frame.mraysPerSecond, 0, 'f', 1)
                             : tr("rendering…"));
    if (frame.qualityPlan)
        showQualityReached(frame);
    else if (frame.renderComplete && !frame.whitted1980) {  // predictions: for the settings
        record_.addRender({frame.settings, frame.seconds, frame.rays});
        // The newest request's frame: the document holds the scene it rendered.
        record_.addViewRender(doc_.contentRevision(), frame.settings, frame.seconds);
    }
    emit frameShown(frame);
}

void MainWindow::showFrameOrMap() {
    const RenderFrame& frame = lastFrame_;
    if (frame.image.isNull()) return;
    if (subdivisionMap_->isChecked() && frame.subdivision && frame.whitted1980) {
        const SubdivisionLevels& levels = *frame.subdivision;
        view_->setFrame(toQImage(
            countMap(levels.levels, levels.width, levels.height, frame.whitted1980->maxLevels)));
        return;
    }
    if (subdivisionMap_->isChecked() && frame.renderComplete)
        statusBar()->showMessage(
            tr("Only Whitted 1980 sampling has a subdivision map: choose it under Antialiasing "
               "in the Render tab"),
            5000);
    view_->setFrame(frame.image, QSizeF(frame.settings.width / double(frame.block),
                                        frame.settings.height / double(frame.block)));
}

// A render to a quality: the target, the depth chosen, the samples it took
// and the error it estimates, with the plan's reasons in the tooltip.
void MainWindow::showQualityReached(const RenderFrame& frame) {
    const QualityPlan& plan = *frame.qualityPlan;
    const QString target = QString::fromStdString(
        plan.target.name.empty() ? describeTarget(plan.target) : plan.target.name);
    passLabel_->setText(
        tr("%1, depth %2: %3").arg(target).arg(plan.maxDepth).arg(passLabel_->text()));
    passLabel_->setToolTip(QString::fromStdString(describeTarget(plan.target) + "\n" + plan.why));
    if (!frame.renderComplete || !frame.qualityReached) return;
    const AdaptiveOutcome& reached = *frame.qualityReached;
    samplesLabel_->setText(QualityChoice::samplesTaken(reached));
    QString estimate = tr("%1, depth %2: about %3")
                           .arg(target)
                           .arg(plan.maxDepth)
                           .arg(QString::fromStdString(psnrText(estimatedPsnr(plan, reached))));
    if (!plan.target.name.empty())
        quality_.noteReached(plan.target.name, tr("%1 s, %2")
                                                   .arg(frame.seconds, 0, 'f', 2)
                                                   .arg(QualityChoice::reachedText(plan, reached)));
    if (reached.tilesAtCap > 0)
        estimate += tr(" (%1 of %2 tiles stopped at %3 samples short of the target)")
                        .arg(reached.tilesAtCap)
                        .arg(reached.tiles)
                        .arg(plan.sampling.maxSamples);
    passLabel_->setText(estimate);
}

bool MainWindow::openFile(const QString& path) {
    // The event loop runs while a file is read: a second open (a shortcut
    // pressed before the progress dialog blocks the window) is refused.
    if (opening_) return false;
    QString error;
    std::optional<Scene> scene;
    {
        const QScopedValueRollback<bool> opening(opening_, true);
        scene = loadSceneShowingProgress(this, path, &error, [this](qint64 done, qint64 total) {
            emit openProgress(done, total);
        });
    }
    if (!scene) {
        showError(tr("Cannot open scene"), error);
        return false;
    }
    doc_.reset(std::move(*scene), path, true);  // the loader validated it
    sceneReplaced();
    addRecentFile(path);
    rememberDirectory(path);
    // Something to edit straight away: the first sphere's properties.
    if (!doc_.scene().spheres.empty()) scenePanel_->select(ItemKind::Sphere, 0);
    return true;
}

void MainWindow::openDialog() {
    if (!maybeSave()) return;
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open Scene"), lastDirectory(), tr(kSceneFilter));
    if (!path.isEmpty()) openFile(path);
}

bool MainWindow::save() {
    if (doc_.filePath().isEmpty()) return saveAs();
    return saveTo(doc_.filePath());
}

bool MainWindow::saveAs() {
    QString start = doc_.filePath();
    if (start.isEmpty()) start = QDir(lastDirectory()).filePath(tr("untitled.json"));
    QFileDialog dialog(this, tr("Save Scene As"), start, tr(kSceneFilter));
    dialog.setObjectName(QStringLiteral("saveAsDialog"));
    dialog.setAcceptMode(QFileDialog::AcceptSave);
    // A name typed without ".json" gets it, and the overwrite question is
    // asked of the name that will be written.
    dialog.setDefaultSuffix(QStringLiteral("json"));
    // Offscreen (the GUI tests) the platform's dialog was seen to hang in exec()
    // on this machine; Qt's own dialog is the one a test can fill in.
    dialog.setOption(QFileDialog::DontUseNativeDialog,
                     QGuiApplication::platformName() == QLatin1String("offscreen"));
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty()) return false;
    return saveTo(dialog.selectedFiles().constFirst());
}

bool MainWindow::saveTo(const QString& path) {
    QString error;
    if (!doc_.save(path, &error)) {
        showError(tr("Cannot save scene"), error);
        return false;
    }
    view_->setHomeCamera(doc_.scene().camera);  // Home now returns to the saved camera
    addRecentFile(path);
    rememberDirectory(path);
    return true;
}

void MainWindow::exportDialog() {
    const QString base =
        doc_.filePath().isEmpty() ? tr("untitled") : QFileInfo(doc_.filePath()).completeBaseName();
    ExportDialog dialog(doc_.scene(), quality_.target(), lastDirectory(), base, this);
    if (dialog.exec() != QDialog::Accepted) return;
    startExport(dialog.settings());
}

void MainWindow::startExport(const ExportSettings& settings) {
    if (export_) return;  // one at a time
    rememberDirectory(settings.path);
    export_ = std::make_unique<ExportJob>(doc_.scene(), settings, plans_);
    exportProgress_ = new QProgressDialog(
        tr("Rendering %1…").arg(QFileInfo(settings.path).fileName()), tr("Cancel"), 0, 100, this);
    exportProgress_->setWindowModality(Qt::WindowModal);
    exportProgress_->setMinimumDuration(300);
    exportProgress_->setAutoClose(false);
    exportProgress_->setAutoReset(false);
    connect(exportProgress_, &QProgressDialog::canceled, export_.get(), &ExportJob::cancel);
    connect(export_.get(), &ExportJob::progress, exportProgress_, &QProgressDialog::setValue);
    connect(
        export_.get(), &ExportJob::finished, this,
        [this](bool ok, const QString& message) {
            if (exportProgress_) exportProgress_->deleteLater();
            export_.reset();
            if (ok)
                statusBar()->showMessage(message, 5000);
            else
                showError(tr("Export failed"), message);
            emit exportFinished(ok, message);
        },
        Qt::QueuedConnection);
    export_->start();
}

int MainWindow::offerRecovery() {
    const std::vector<Recovery> waiting = Autosave::orphans(autosave_->directory());
    if (waiting.empty()) return 0;
    const Recovery& r = waiting.front();
    const QString what = sceneName(r.originalPath, tr("an untitled scene"));
    // The copy may be of another scene than the one just opened: say that
    // restoring replaces it, so that nobody loses track of which file is shown.
    const QString instead = r.originalPath == doc_.filePath()
                                ? QString()
                                : tr(" Restoring opens it in place of %1.")
                                      .arg(sceneName(doc_.filePath(), tr("the new scene")));
    auto* box = new QMessageBox(
        QMessageBox::Question, tr("Restore unsaved changes"),
        tr("Whitted stopped without saving changes to %1. A copy from %2 was kept.\n\n"
           "Restore it? The restored scene is marked unsaved; undo returns to the file.%3")
            .arg(what, QLocale().toString(r.written.toLocalTime(), QLocale::ShortFormat), instead),
        QMessageBox::NoButton, this);
    box->setObjectName(QStringLiteral("recoveryOffer"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    QPushButton* restoreButton = box->addButton(tr("Restore"), QMessageBox::AcceptRole);
    restoreButton->setObjectName(QStringLiteral("restoreButton"));
    QPushButton* discardButton = box->addButton(tr("Discard"), QMessageBox::DestructiveRole);
    discardButton->setObjectName(QStringLiteral("discardButton"));
    box->setDefaultButton(restoreButton);
    connect(box, &QMessageBox::buttonClicked, this, [this, r, restoreButton](QAbstractButton* b) {
        if (b == restoreButton) restore(r);
        Autosave::discard(r);
        // The next one, if another editor died too.
        QTimer::singleShot(0, this, [this] { offerRecovery(); });
    });
    box->open();
    return int(waiting.size());
}

void MainWindow::restore(const Recovery& r) {
    // The recovered scene is one undo step on top of the file it came from, so
    // it shows as unsaved and undo shows the file; an untitled scene goes on
    // top of the New template.
    QString error;
    if (r.originalPath.isEmpty() || !doc_.load(r.originalPath, &error))
        doc_.reset(newSceneTemplate(), r.originalPath);
    tradeoffView_->sceneReplaced();  // whatever was pinned or measured was of another scene
    const Scene recovered = r.scene;
    doc_.edit(tr("Restore unsaved changes"), [&](Scene& s) { s = recovered; });
}

bool MainWindow::maybeSave() {
    if (!doc_.isModified()) return true;
    const auto answer = QMessageBox::warning(
        this, tr("Unsaved changes"), tr("The scene has unsaved changes. Save them first?"),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save) return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::showError(const QString& title, const QString& message) {
    lastError_ = message;
    // Window-modal but not blocking: the editor (and a test driving it) carries on.
    auto* box = new QMessageBox(QMessageBox::Warning, title, message, QMessageBox::Ok, this);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

void MainWindow::updateTitle() {
    const QString name = sceneName(doc_.filePath(), tr("Untitled"));
    setWindowTitle(tr("%1[*] — Whitted").arg(name));
    setWindowModified(doc_.isModified());
}

void MainWindow::addRecentFile(const QString& path) {
    QSettings settings;
    QStringList files = settings.value("recentFiles").toStringList();
    const QString absolute = QFileInfo(path).absoluteFilePath();
    files.removeAll(absolute);
    files.prepend(absolute);
    while (files.size() > kMaxRecentFiles) files.removeLast();
    settings.setValue("recentFiles", files);
    rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu() {
    recentMenu_->clear();
    const QStringList files = QSettings().value("recentFiles").toStringList();
    for (const QString& f : files)
        recentMenu_
            ->addAction(QFileInfo(f).fileName(), this,
                        [this, f] {
                            if (maybeSave()) openFile(f);
                        })
            ->setToolTip(f);
    recentMenu_->setEnabled(!files.isEmpty());
}

QString MainWindow::lastDirectory() const {
    return QSettings().value("lastDirectory", QDir::currentPath()).toString();
}

void MainWindow::rememberDirectory(const QString& path) {
    QSettings().setValue("lastDirectory", QFileInfo(path).absolutePath());
}

void MainWindow::closeEvent(QCloseEvent* e) {
    if (!maybeSave()) {
        e->ignore();
        return;
    }
    QSettings settings;
    settings.setValue("window/geometry", saveGeometry());
    settings.setValue("window/state", saveState());
    e->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* e) {
    if (e->mimeData()->hasUrls() && e->mimeData()->urls().value(0).isLocalFile())
        e->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* e) {
    const QString path = e->mimeData()->urls().value(0).toLocalFile();
    if (path.isEmpty() || !maybeSave()) return;
    openFile(path);
    e->acceptProposedAction();
}

}  // namespace whitted::ui
