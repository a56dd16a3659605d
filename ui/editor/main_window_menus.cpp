// The main window's menus, tool bar and help: every command the window offers,
// each an action with its shortcut and tool tip, so that the menus, the tool
// bar and Help > Keyboard and Mouse all show the same bindings.
#include <QActionGroup>
#include <QDockWidget>
#include <QIcon>
#include <QInputDialog>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QToolBar>
#include <QToolButton>

#include <string>
#include <unordered_set>
#include <vector>

#include "document/scene_undo_keys.h"
#include "editor/help_dialogs.h"
#include "editor/main_window.h"
#include "panels/preset_controls.h"
#include "panels/scene_panel.h"
#include "tradeoff_dock/tradeoff_view.h"
#include "viewport/render_view.h"

namespace whitted::ui {

namespace {

// The desktop theme's icon where there is one, ours (resources/) otherwise.
QIcon themeIcon(const char* name) {
    const QString id = QLatin1String(name);
    return QIcon::fromTheme(id, QIcon(QStringLiteral(":/icons/actions/%1.svg").arg(id)));
}

}  // namespace

void MainWindow::buildMenus() {
    buildFileMenu();
    buildEditMenu();
    buildRenderMenu();
    buildToolBar();
    buildViewMenu();
    buildHelpMenu();
    addShortcutsToToolTips(this);
}

void MainWindow::buildFileMenu() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&New"), QKeySequence::New, this, [this] {
        if (!maybeSave()) return;
        doc_.reset(newSceneTemplate(), QString());
        sceneReplaced();
    });
    openAction_ = file->addAction(themeIcon("document-open"), tr("&Open…"), QKeySequence::Open,
                                  this, &MainWindow::openDialog);
    recentMenu_ = file->addMenu(tr("Open &Recent"));
    file->addSeparator();
    saveAction_ = file->addAction(themeIcon("document-save"), tr("&Save"), QKeySequence::Save, this,
                                  &MainWindow::save);
    // Spelled out: Qt's standard keys for these are empty outside GNOME and KDE.
    file->addAction(tr("Save &As…"), QKeySequence(tr("Ctrl+Shift+S")), this, &MainWindow::saveAs);
    file->addSeparator();
    exportAction_ = file->addAction(themeIcon("document-export"), tr("&Export Image…"),
                                    QKeySequence(tr("Ctrl+E")), this, &MainWindow::exportDialog);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence(tr("Ctrl+Q")), this, &QWidget::close);
    for (QAction* a : file->actions())
        if (!a->isSeparator() && a->objectName().isEmpty())
            a->setObjectName(a->text().remove(QLatin1Char('&')).remove(QStringLiteral("…")));
}

void MainWindow::buildEditMenu() {
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    undoAction_ = doc_.undoStack()->createUndoAction(this, tr("&Undo"));
    undoAction_->setObjectName(QStringLiteral("undo"));
    undoAction_->setShortcuts(QKeySequence::Undo);
    undoAction_->setIcon(themeIcon("edit-undo"));
    redoAction_ = doc_.undoStack()->createRedoAction(this, tr("&Redo"));
    redoAction_->setObjectName(QStringLiteral("redo"));
    redoAction_->setShortcuts({QKeySequence(tr("Ctrl+Shift+Z")), QKeySequence(tr("Ctrl+Y"))});
    redoAction_->setIcon(themeIcon("edit-redo"));
    edit->addAction(undoAction_);
    edit->addAction(redoAction_);
    // Ctrl+Z undoes the scene even while a field that was just typed in has the focus.
    new SceneUndoKeys(this, {undoAction_, redoAction_});
    edit->addSeparator();
    edit->addAction(scenePanel_->addAction());
    edit->addAction(scenePanel_->duplicateAction());
    QAction* duplicateAndMove =
        edit->addAction(tr("Duplicate and &Move"), this, [this] { this->duplicateAndMove(); });
    duplicateAndMove->setObjectName(QStringLiteral("duplicateAndMove"));
    duplicateAndMove->setShortcut(QKeySequence(tr("Shift+D")));
    edit->addAction(scenePanel_->deleteAction());
    edit->addAction(scenePanel_->renameAction());
    edit->addSeparator();
    buildClipboardActions(edit);
    edit->addSeparator();
    buildSelectMenu(edit->addMenu(tr("&Select")));
}

void MainWindow::buildSelectMenu(QMenu* menu) {
    auto add = [&](const QString& text, const char* name, const QKeySequence& key, auto run) {
        QAction* a = menu->addAction(text, this, run);
        a->setObjectName(QLatin1String(name));
        a->setShortcut(key);
        return a;
    };
    SceneSelection* selection = doc_.selection();
    // Of the list shown: the spheres, lights or materials tab.
    add(tr("&All"), "selectAll", QKeySequence(Qt::Key_A), [this, selection] {
        const ItemKind kind = scenePanel_->currentKind();
        std::vector<int> all(itemCount(doc_.scene(), kind));
        for (int i = 0; i < int(all.size()); ++i) all[i] = i;
        selection->set(kind, std::move(all), selection->active());
    });
    add(tr("&None"), "selectNone", QKeySequence(Qt::ALT | Qt::Key_A),
        [selection] { selection->clear(); });
    add(tr("&Invert"), "selectInvert", QKeySequence(Qt::CTRL | Qt::Key_I), [this, selection] {
        const ItemKind kind = scenePanel_->currentKind();
        std::vector<int> others;
        for (int i = 0; i < itemCount(doc_.scene(), kind); ++i)
            if (!selection->contains(kind, i)) others.push_back(i);
        selection->set(kind, std::move(others));
    });
    add(tr("Same &Material"), "selectSameMaterial", QKeySequence(Qt::SHIFT | Qt::Key_L),
        [this] { selectSameMaterial(); })
        ->setStatusTip(tr("Select every sphere of the selected materials, or of the selected "
                          "spheres' materials"));
}

void MainWindow::selectSameMaterial() {
    SceneSelection* selection = doc_.selection();
    const Scene& s = doc_.scene();
    std::unordered_set<std::string> materials;
    for (int i : selection->indices()) {
        if (selection->kind() == ItemKind::Material) materials.insert(s.materials[i].name);
        if (selection->kind() == ItemKind::Sphere) materials.insert(s.spheres[i].material);
    }
    if (materials.empty()) return;
    std::vector<int> spheres;
    for (int i = 0; i < int(s.spheres.size()); ++i)
        if (materials.contains(s.spheres[i].material)) spheres.push_back(i);
    const int active = selection->kind() == ItemKind::Sphere ? selection->active() : -1;
    selection->set(ItemKind::Sphere, std::move(spheres), active);
}

void MainWindow::duplicateAndMove() {
    const SceneSelection& selection = *doc_.selection();
    if (selection.kind() == ItemKind::Material || selection.empty()) return;
    doc_.beginGesture(tr("Duplicate and move %1")
                          .arg(selection.count() == 1
                                   ? itemName(doc_.scene(), selection.kind(), selection.active())
                                   : countedNoun(selection.count(), selection.kind())));
    scenePanel_->duplicateItem(selection.kind());
    moveWithinGesture();
}

void MainWindow::buildClipboardActions(QMenu* edit) {
    QAction* copy =
        edit->addAction(tr("&Copy"), QKeySequence::Copy, this, [this] { copySelection(); });
    copy->setObjectName(QStringLiteral("copy"));
    copy->setStatusTip(
        tr("Copy the selected spheres (with their materials) or lights, to paste "
           "into this or another scene"));
    QAction* paste =
        edit->addAction(tr("&Paste"), QKeySequence::Paste, this, [this] { pasteClipboard(); });
    paste->setObjectName(QStringLiteral("paste"));
    paste->setStatusTip(tr("Add the copied spheres and lights to this scene"));
}

bool MainWindow::addSphereAtPointer() {
    const auto centre = view_->restingSpotUnderPointer(ScenePanel::kNewSphereRadius);
    if (!centre) return false;
    doc_.beginGesture(tr("Add sphere"));
    scenePanel_->addSphere(centre);
    moveWithinGesture();
    return true;
}

void MainWindow::moveWithinGesture() {
    if (!view_->startMove()) {
        doc_.endGesture();
        return;
    }
    connect(
        view_, &RenderView::moveFinished, this, [this] { doc_.endGesture(); },
        Qt::SingleShotConnection);
}

void MainWindow::buildRenderMenu() {
    QMenu* renderMenu = menuBar()->addMenu(tr("&Render"));
    // The Render tab's presets, from the keyboard too; the one the settings
    // match is ticked (none when they are custom).
    presetGroup_ = new QActionGroup(this);
    for (std::size_t i = 0; i < kRenderPresets.size(); ++i) {
        const RenderPreset& preset = kRenderPresets[i];
        const QString name = QString::fromUtf8(preset.name.data(), qsizetype(preset.name.size()));
        QAction* a = renderMenu->addAction(tr("%1 Preset").arg(name), this, [this, &preset] {
            QString error;
            if (!PresetControls::apply(&doc_, &quality_, preset, &error))
                showError(tr("Cannot apply preset"), error);
            tickPreset();
        });
        a->setShortcut(QKeySequence(tr("Ctrl+%1").arg(i + 1)));
        a->setObjectName(QStringLiteral("preset%1").arg(name));
        a->setCheckable(true);
        presetGroup_->addAction(a);
    }
    presetGroup_->setExclusionPolicy(QActionGroup::ExclusionPolicy::ExclusiveOptional);
    connect(&doc_, &SceneDocument::sceneChanged, this, &MainWindow::tickPreset);
    renderMenu->addSeparator();
    tradeoffView_->pinAction()->setShortcut(QKeySequence(tr("Ctrl+Shift+P")));
    tradeoffView_->pinAction()->setIcon(themeIcon("pin"));
    renderMenu->addAction(tradeoffView_->pinAction());
    renderMenu->addAction(tradeoffView_->unpinAction());
    renderMenu->addSeparator();
    tradeoffView_->measureAction()->setShortcut(QKeySequence(tr("Ctrl+Shift+M")));
    renderMenu->addAction(tradeoffView_->measureAction());
    renderMenu->addAction(tradeoffView_->cancelMeasureAction());
}

void MainWindow::tickPreset() {
    const int match = PresetControls::matchingPreset(doc_.scene().render);
    const QList<QAction*> actions = presetGroup_->actions();
    for (int i = 0; i < actions.size(); ++i) actions[i]->setChecked(i == match);
}

void MainWindow::buildViewMenu() {
    QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
    QMenu* cameraMenu = viewMenu->addMenu(tr("&Camera"));
    for (QAction* a : view_->cameraActions()) {
        // Reset and Frame work from anywhere; the moves while the view has focus.
        if (a->shortcutContext() == Qt::WindowShortcut)
            viewMenu->insertAction(cameraMenu->menuAction(), a);
        else
            cameraMenu->addAction(a);
    }
    subdivisionMap_ = viewMenu->addAction(tr("Su&bdivision Map"));
    subdivisionMap_->setObjectName(QStringLiteral("showSubdivisionMap"));
    subdivisionMap_->setCheckable(true);
    subdivisionMap_->setStatusTip(
        tr("How deep Whitted 1980 sampling cut each pixel: black not at all, pale yellow the "
           "most (Render tab, Antialiasing)"));
    connect(subdivisionMap_, &QAction::toggled, this, [this] { showFrameOrMap(); });
    QAction* snap = viewMenu->addAction(tr("Snap &Step…"), this, [this] { askSnapStep(); });
    snap->setObjectName(QStringLiteral("snapStep"));
    snap->setStatusTip(tr("The grid that Ctrl snaps a move to"));
    view_->setMoveGrid(QSettings().value("view/snapStep", RenderView::kMoveGrid).toDouble());
    viewMenu->addSeparator();
    viewMenu->addAction(toolBar_->toggleViewAction());
    for (QDockWidget* dock : findChildren<QDockWidget*>())
        viewMenu->addAction(dock->toggleViewAction());
}

void MainWindow::askSnapStep() {
    auto* dialog = new QInputDialog(this);
    dialog->setObjectName(QStringLiteral("snapStepDialog"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(tr("Snap Step"));
    dialog->setLabelText(tr("Ctrl during a move snaps it to steps of (scene units):"));
    dialog->setInputMode(QInputDialog::DoubleInput);
    dialog->setDoubleRange(1e-6, 1e6);
    dialog->setDoubleDecimals(6);
    dialog->setDoubleValue(view_->moveGrid());
    connect(dialog, &QInputDialog::doubleValueSelected, this, [this](double step) {
        view_->setMoveGrid(step);
        QSettings().setValue("view/snapStep", view_->moveGrid());
    });
    dialog->open();
}

void MainWindow::buildHelpMenu() {
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    QAction* keys = help->addAction(tr("&Keyboard and Mouse"), QKeySequence::HelpContents, this,
                                    [this] { showKeyboardHelp(this, controls()); });
    keys->setObjectName(QStringLiteral("keyboardHelpAction"));
    QAction* about = help->addAction(tr("&About Whitted"), this, [this] { showAbout(this); });
    about->setObjectName(QStringLiteral("aboutAction"));
}

QList<ControlRow> MainWindow::controls() {
    return controlRows(this, RenderView::mouseControls());
}

void MainWindow::buildToolBar() {
    QToolBar* bar = toolBar_ = addToolBar(tr("Tool Bar"));
    bar->setObjectName(QStringLiteral("mainToolBar"));
    bar->addActions({openAction_, saveAction_});
    bar->addSeparator();
    bar->addActions({undoAction_, redoAction_});
    bar->addSeparator();
    bar->addAction(exportAction_);
    // The presets as one button with a menu: their names and keys are in it.
    auto* presets = new QToolButton(bar);
    presets->setObjectName(QStringLiteral("presetButton"));
    presets->setIcon(themeIcon("preset"));
    presets->setText(tr("Preset"));
    presets->setToolTip(tr("Render quality presets (Ctrl+1 to Ctrl+3)"));
    presets->setPopupMode(QToolButton::InstantPopup);
    auto* presetMenu = new QMenu(presets);
    presetMenu->addActions(presetGroup_->actions());
    presets->setMenu(presetMenu);
    bar->addWidget(presets);
    bar->addAction(tradeoffView_->pinAction());
}

}  // namespace whitted::ui
