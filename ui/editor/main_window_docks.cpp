// The main window's docks: the scene lists on the left, the settings on the
// right with the Precision Check under them, the Trade-off dock under the
// render view, and the room each is given when shown.
#include <QAction>
#include <QDockWidget>
#include <QTabWidget>

#include "editor/main_window.h"
#include "panels/property_panels.h"
#include "panels/scene_panel.h"
#include "precision_dock/precision_view.h"
#include "ray_tree_dock/ray_tree_view.h"
#include "tradeoff_dock/tradeoff_view.h"
#include "viewport/render_view.h"

namespace whitted::ui {

void MainWindow::buildDocks() {
    scenePanel_ = new ScenePanel(&doc_);
    scenePanel_->setAddSphereHere([this] { return addSphereAtPointer(); });
    auto* sceneDock = new QDockWidget(tr("Scene"), this);
    sceneDock->setObjectName("sceneDock");
    sceneDock->setWidget(scenePanel_);
    addDockWidget(Qt::LeftDockWidgetArea, sceneDock);

    propertyPanel_ = new PropertyPanel(&doc_);
    auto* tabs = new QTabWidget;
    tabs->setObjectName("settingsTabs");
    tabs->addTab(propertyPanel_, tr("Properties"));
    tabs->addTab(new CameraPanel(&doc_), tr("Camera"));
    tabs->addTab(new RenderSettingsPanel(&doc_, &record_, &quality_), tr("Render"));
    auto* settingsDock = new QDockWidget(tr("Settings"), this);
    settingsDock->setObjectName("settingsDock");
    settingsDock->setWidget(tabs);
    addDockWidget(Qt::RightDockWidgetArea, settingsDock);

    // Hidden until asked for from the View menu: it renders the scene twice more.
    precisionView_ = new PrecisionView(&doc_);
    auto* precisionDock = new QDockWidget(tr("Precision Check"), this);
    precisionDock->setObjectName("precisionDock");
    precisionDock->setWidget(precisionView_);
    // It compares only once the main render is done: it never delays what the user edits.
    connect(this, &MainWindow::frameShown, precisionView_, &PrecisionView::mainFrameShown);
    addDockWidget(Qt::RightDockWidgetArea, precisionDock);
    splitDockWidget(settingsDock, precisionDock, Qt::Vertical);
    precisionDock->hide();
    QAction* togglePrecision = precisionDock->toggleViewAction();
    togglePrecision->setObjectName("togglePrecisionView");
    togglePrecision->setShortcut(QKeySequence(tr("Ctrl+Shift+F")));
    connect(precisionDock, &QDockWidget::visibilityChanged, this,
            [this, settingsDock, precisionDock](bool visible) {
                if (visible) giveHalfOfColumn(settingsDock, precisionDock);
            });
    buildTradeoffDock();
    buildRayTreeDock();

    connect(scenePanel_, &ScenePanel::selectionChanged, this, [this, tabs](ItemKind, int index) {
        if (index >= 0) tabs->setCurrentWidget(propertyPanel_);
    });
}

void MainWindow::buildTradeoffDock() {
    // Hidden until asked for. Under the render view, where a plot and a table
    // have the width they need; the side columns keep their full height.
    tradeoffView_ = new TradeoffView(&doc_, &record_);
    auto* dock = new QDockWidget(tr("Trade-off"), this);
    dock->setObjectName("tradeoffDock");
    dock->setWidget(tradeoffView_);
    setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    addDockWidget(Qt::BottomDockWidgetArea, dock);
    dock->hide();
    QAction* toggle = dock->toggleViewAction();
    toggle->setObjectName("toggleTradeoffView");
    toggle->setShortcut(QKeySequence(tr("Ctrl+Shift+T")));
    connect(dock, &QDockWidget::visibilityChanged, this, [this, dock](bool visible) {
        // Shown at its minimum height, the plot would be a strip: 40 % of the window.
        if (visible && !dock->isFloating() && dockWidgetArea(dock) == Qt::BottomDockWidgetArea &&
            dock->height() < height() / 4)
            resizeDocks({dock}, {height() * 2 / 5}, Qt::Vertical);
    });
    // Pinning or measuring shows where the points go.
    for (QAction* a : {tradeoffView_->pinAction(), tradeoffView_->measureAction()})
        connect(a, &QAction::triggered, dock, [dock] {
            dock->show();
            dock->raise();
        });
    connect(this, &MainWindow::frameShown, tradeoffView_, &TradeoffView::frameShown);
}

void MainWindow::buildRayTreeDock() {
    // Under the render view beside the Trade-off dock, hidden until a pixel is
    // Ctrl+clicked or it is asked for: the tree's rows want the window's width.
    rayTreeView_ = new RayTreeView(&doc_);
    auto* dock = new QDockWidget(tr("Ray Tree"), this);
    dock->setObjectName("rayTreeDock");
    dock->setWidget(rayTreeView_);
    addDockWidget(Qt::BottomDockWidgetArea, dock);
    dock->hide();
    QAction* toggle = dock->toggleViewAction();
    toggle->setObjectName("toggleRayTreeView");
    toggle->setShortcut(QKeySequence(tr("Ctrl+Shift+R")));
    toggle->setStatusTip(tr("The rays that make a pixel's colour: Ctrl+click a pixel"));
    connect(view_, &RenderView::pixelInspected, this, [this, dock](QPoint pixel) {
        rayTreeView_->inspect(pixel);
        dock->show();
        dock->raise();
    });
    // In the view's context and not the window's: the dock hides (and says
    // so) while the window is being destroyed, when it is a window no more.
    connect(rayTreeView_, &RayTreeView::overlayChanged, view_, [view = view_, tree = rayTreeView_] {
        if (tree->isVisible())
            view->setInspectedRays(tree->rays(), tree->highlightedRay());
        else
            view->setInspectedRays({}, -1);
    });
    connect(dock, &QDockWidget::visibilityChanged, this, [this, dock](bool visible) {
        if (visible && !dock->isFloating() && dockWidgetArea(dock) == Qt::BottomDockWidgetArea &&
            dock->height() < height() / 4)
            resizeDocks({dock}, {height() / 3}, Qt::Vertical);
    });
}

void MainWindow::giveHalfOfColumn(QDockWidget* settingsDock, QDockWidget* dock) {
    // Squeezed under the settings, a plot or heat map would be a thumbnail.
    const int column = settingsDock->height() + dock->height();
    if (settingsDock->isHidden() || dock->isFloating() || dock->height() >= column * 2 / 5) return;
    resizeDocks({settingsDock, dock}, {column / 2, column - column / 2}, Qt::Vertical);
}

}  // namespace whitted::ui
