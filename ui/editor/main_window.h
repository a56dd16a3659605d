// The editor's main window: the render view in the middle, the scene lists on
// the left, properties, camera and render settings on the right, the
// Precision Check and Trade-off docks (main_window_docks.cpp), the File, Edit,
// Render, View and Help menus and the tool bar (main_window_menus.cpp). It
// owns the document and the render worker and wires them together: every
// scene change restarts the render, every frame that is not stale reaches the
// view, the status bar and the Trade-off dock.
#pragma once

#include <QLabel>
#include <QMainWindow>
#include <QPointer>
#include <QTimer>

#include <cstdint>
#include <memory>

#include "document/quality_choice.h"
#include "document/scene_document.h"
#include "editor/help_dialogs.h"
#include "prediction/probe_predictor.h"
#include "prediction/render_record.h"
#include "viewport/render_worker.h"

class QAction;
class QActionGroup;
class QDockWidget;
class QToolBar;
class QMenu;
class QProgressDialog;

namespace whitted::ui {

class RenderView;
class ScenePanel;
class PrecisionView;
class RayTreeView;
class Autosave;
struct Recovery;
class TradeoffView;
class FloatRangeWarning;
class PropertyPanel;
class ExportJob;
struct ExportSettings;

class MainWindow : public QMainWindow {
    Q_OBJECT
  public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Opens a scene file without asking about unsaved changes; on failure shows
    // core's message and keeps the current scene. Returns whether it opened.
    // The file is read on a worker thread with a progress dialog (scene_loading.h);
    // the event loop runs meanwhile, and returns when the file is read.
    bool openFile(const QString& path);
    // Starts exporting with these settings (what the Export dialog does after OK).
    void startExport(const ExportSettings& settings);

    SceneDocument* document() { return &doc_; }
    RenderView* renderView() { return view_; }
    const RenderWorker& renderWorker() const { return worker_; }
    ScenePanel* scenePanel() { return scenePanel_; }
    PropertyPanel* propertyPanel() { return propertyPanel_; }
    PrecisionView* precisionView() { return precisionView_; }
    TradeoffView* tradeoffView() { return tradeoffView_; }
    RayTreeView* rayTreeView() { return rayTreeView_; }
    RenderRecord* renderRecord() { return &record_; }
    QualityChoice* qualityChoice() { return &quality_; }
    FloatRangeWarning* floatRangeWarning() { return floatRangeWarning_; }
    QString lastError() const { return lastError_; }  // the last message shown to the user
    Autosave* autosave() { return autosave_.get(); }

    // Offers, one after the other, to restore the unsaved edits of editors that
    // crashed or were killed (Autosave::orphans). Non-blocking message boxes,
    // object name "recoveryOffer", buttons "restoreButton" and "discardButton".
    // Returns how many are waiting.
    int offerRecovery();

    // A scene to start from for File > New: a ball on a checker floor, one light.
    static Scene newSceneTemplate();

  signals:
    // A frame reached the view (stale frames never do).
    void frameShown(const whitted::ui::RenderFrame& frame);
    void exportFinished(bool ok, const QString& message);
    // While openFile() reads a file: bytes read so far and the file's size.
    void openProgress(qint64 done, qint64 total);

  protected:
    void closeEvent(QCloseEvent* e) override;
    void dragEnterEvent(QDragEnterEvent* e) override;
    void dropEvent(QDropEvent* e) override;

  private:
    void connectRendersAndPredictions();
    void buildStatusBar();
    void restorePlacement();

    // main_window_menus.cpp
    void buildMenus();
    void buildFileMenu();
    void buildEditMenu();
    void buildRenderMenu();
    void buildViewMenu();
    void buildHelpMenu();
    // View > Snap Step: the grid Ctrl snaps a move to, remembered (non-blocking
    // dialog, object name "snapStepDialog").
    void askSnapStep();
    // Blender's Shift+D: a copy of the selected sphere or light that moves with
    // the pointer at once (RenderView::startMove); Escape leaves the copy where
    // the original is. The copy and its move are one undo step.
    void duplicateAndMove();
    // Edit > Select: All (A), None (Alt+A), Invert (Ctrl+I) of the list shown,
    // and Same Material (Shift+L).
    void buildSelectMenu(QMenu* menu);
    // The spheres of the selected materials, or of the selected spheres' materials.
    void selectSameMaterial();
    // Ctrl+C and Ctrl+V: the selection as a scene-file fragment (scene_fragment.h)
    // on the system clipboard, so it pastes into any editor window.
    void buildClipboardActions(QMenu* edit);
    void copySelection();
    void pasteClipboard();
    // Shift+A on the Spheres tab with the pointer over the picture: a new
    // sphere resting on what is under the pointer, then moving with it as
    // after Shift+D. False, and nothing, when the pointer is elsewhere.
    bool addSphereAtPointer();
    // The move of what was just added or copied inside the gesture begun for
    // it; the gesture ends with the move.
    void moveWithinGesture();
    void buildToolBar();
    void tickPreset();  // ticks the Render menu's preset the settings match
    QList<ControlRow> controls();

    // main_window_docks.cpp
    void buildDocks();
    void buildTradeoffDock();
    void buildRayTreeDock();
    // Shown under the settings, a dock squeezed small gets half of the column.
    void giveHalfOfColumn(QDockWidget* settingsDock, QDockWidget* dock);

    void sceneReplaced();
    void newScene();
    void openDialog();
    bool save();
    bool saveAs();
    bool saveTo(const QString& path);
    void exportDialog();
    bool maybeSave();  // false: the user cancelled
    void showError(const QString& title, const QString& message);
    void updateTitle();
    void addRecentFile(const QString& path);
    void rebuildRecentMenu();
    QString lastDirectory() const;
    void rememberDirectory(const QString& path);
    void onFrame(const RenderFrame& frame);
    void showFrameOrMap();
    void showQualityReached(const RenderFrame& frame);
    void requestRender();
    // Asks predictor_ once edits have paused and the newest edit's first
    // frame is on screen: the user waits for that picture, and a prediction
    // running beside its render took a core from it.
    void predictWhenShown();

    SceneDocument doc_;
    RenderRecord record_;
    std::uint64_t renderedRevision_ = 0;  // the document's content the record's renders are of
    QualityChoice quality_;
    PlanMemo plans_;  // made once for the view, its prediction and an export alike
    ProbePredictor predictor_{plans_};  // the Render tab's predictions for scenes never measured
    QTimer predictPause_;               // asks predictor_ once edits pause this long
    static constexpr int kPredictPauseMs = 100;
    bool predictionDue_ = false;     // the pause is over: predict once a frame is shown
    bool newestFrameShown_ = false;  // a frame of the newest render request is on screen
    RenderWorker worker_{plans_};
    RenderView* view_ = nullptr;
    ScenePanel* scenePanel_ = nullptr;
    PropertyPanel* propertyPanel_ = nullptr;
    PrecisionView* precisionView_ = nullptr;
    TradeoffView* tradeoffView_ = nullptr;
    RayTreeView* rayTreeView_ = nullptr;
    FloatRangeWarning* floatRangeWarning_ = nullptr;
    QMenu* recentMenu_ = nullptr;
    QToolBar* toolBar_ = nullptr;
    QActionGroup* presetGroup_ = nullptr;
    QAction *openAction_ = nullptr, *saveAction_ = nullptr, *exportAction_ = nullptr;
    QAction *undoAction_ = nullptr, *redoAction_ = nullptr;
    QLabel* passLabel_ = nullptr;
    QLabel* samplesLabel_ = nullptr;
    // The last frame, and how deep Whitted 1980 sampling cut its pixels (null
    // for other samplers): what View > Subdivision Map switches between.
    RenderFrame lastFrame_;
    QAction* subdivisionMap_ = nullptr;
    QLabel* timeLabel_ = nullptr;
    QLabel* speedLabel_ = nullptr;
    QString lastError_;
    bool opening_ = false;  // openFile() is reading a file
    void restore(const Recovery& recovery);

    std::unique_ptr<ExportJob> export_;
    std::unique_ptr<Autosave> autosave_;
    QPointer<QProgressDialog> exportProgress_;
};

}  // namespace whitted::ui
