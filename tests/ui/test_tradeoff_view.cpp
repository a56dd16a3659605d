// GUI tests of the speed/accuracy trade in the editor: the Render tab's presets
// and predictions, and the Trade-off dock (Pin as Reference, Measure). The real
// MainWindow driven offscreen, as tests/ui/test_main_window.cpp does.
//
// Errors shown are checked against core's measureError() called directly on
// the linear images the frames carry: both sides compute the same function of
// the same pixels, so they must be equal, not close.
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QElapsedTimer>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStyle>
#include <QTabWidget>
#include <QTableWidget>
#include <QTest>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <string>

#include "analysis/quality_check.h"
#include "analysis/render_presets.h"
#include "analysis/tradeoff.h"
#include "editor/main_window.h"
#include "image/image_error.h"
#include "plot/plot_widget.h"
#include "prediction/render_record.h"
#include "prediction/settings_prediction.h"
#include "scene/scene_io.h"
#include "support/main_window_fixture.h"
#include "support/test_support.h"
#include "tradeoff_dock/tradeoff_view.h"

namespace whitted::ui {
namespace {

constexpr int kTimeoutMs = 30000;  // renders take milliseconds; CI machines are shared

// A grid small enough for a 64 x 48 scene to finish in a fraction of a second.
TradeoffGrid tinyGrid() {
    TradeoffGrid g;
    g.samples = {1, 2, 4};
    g.depths = {0, 1, 2};
    g.precisions = {Precision::Float, Precision::Double};
    g.scales = {1.0};
    g.minRuns = 1;
    g.maxRuns = 1;
    g.minSeconds = 0.0;
    return g;
}

// Enough work that a run cannot finish before a cancel: 126 points at 160 x 120.
TradeoffGrid slowGrid() {
    TradeoffGrid g = tinyGrid();
    g.samples = {1, 2, 4, 8, 16, 32, 64};
    g.depths = {0, 1, 2, 3, 4, 5, 6, 7, 8};
    return g;
}

// A window on a copy of the seed scene at `width` x `height`, its first render finished.
class TradeoffViewTest : public EditorWindowTest {
  protected:
    TradeoffViewTest() { renderTimeoutMs = kTimeoutMs; }

    void SetUp() override { open(kWidth, kHeight); }

    void open(int width, int height) {
        writeSeedFile(width, height);
        if (!window) {
            ASSERT_TRUE(showWindow({1400, 900}));
        }
        doc = window->document();
        view = window->tradeoffView();
        ASSERT_NE(view, nullptr);
        ASSERT_TRUE(openAndWait(scenePath));
    }

    // What QComboBox does when the user picks item `index`.
    void choosePreset(int index) {
        auto* combo = child<QComboBox>("renderPreset");
        combo->setCurrentIndex(index);
        emit combo->activated(index);
    }

    // Triggers Pin as Reference on a noisy image; returns the warning it shows.
    QMessageBox* pinNoisy() {
        QAction* action = view->pinAction();
        EXPECT_TRUE(action->isEnabled());
        action->trigger();
        // The one on screen: an answered one is deleted only later.
        QMessageBox* box = nullptr;
        for (auto* b : window->findChildren<QMessageBox*>(QStringLiteral("noisyPinWarning")))
            if (b->isVisible()) box = b;
        EXPECT_NE(box, nullptr);
        return box;
    }

    // Clicks a button of `box`, as the user does.
    static void click(QMessageBox* box, const char* button) {
        auto* b = box->findChild<QPushButton*>(QString::fromLatin1(button));
        ASSERT_NE(b, nullptr) << button;
        QTest::mouseClick(b, Qt::LeftButton);
    }

    // Pins the finished frame (the seed's 1 sample per pixel: past the warning); returns it.
    RenderFrame pin() {
        QMessageBox* box = pinNoisy();
        if (box) click(box, "pinAnywayButton");
        EXPECT_TRUE(view->isPinned());
        return log->lastComplete;
    }

    // Runs Measure on the current scene with `grid`; false on a timeout.
    bool measure(const TradeoffGrid& grid, int referenceSamples) {
        view->setMeasureGrid(grid, referenceSamples);
        QSignalSpy finished(view, &TradeoffView::measureFinished);
        if (!view->startMeasure()) return false;
        return finished.wait(kTimeoutMs);
    }

    TradeoffView* view = nullptr;
};

// ---------------------------------------------------------------------------
// Presets

TEST_F(TradeoffViewTest, Preset_EachSetsExactlyItsValuesAsOneUndoStep_UndoRestores) {
    // From settings that match no preset, so each choice changes something.
    ASSERT_TRUE(doc->edit(QStringLiteral("custom"), [](Scene& s) {
        s.render.samplesPerPixel = 3;
        s.render.maxDepth = 7;
    }));
    auto* combo = child<QComboBox>("renderPreset");
    ASSERT_EQ(combo->count(), int(kRenderPresets.size()) + 1);
    EXPECT_EQ(combo->currentIndex(), 0);
    EXPECT_EQ(combo->currentText(), QStringLiteral("Custom"));
    const Scene before = doc->scene();
    const int steps = doc->undoStack()->count();
    for (std::size_t i = 0; i < kRenderPresets.size(); ++i) {
        const RenderPreset& preset = kRenderPresets[i];
        SCOPED_TRACE(std::string(preset.name));
        choosePreset(int(i) + 1);
        Scene want = before;
        want.render.samplesPerPixel = preset.samplesPerPixel;
        want.render.maxDepth = preset.maxDepth;
        want.render.precision = preset.precision;
        EXPECT_EQ(doc->scene(), want);
        EXPECT_EQ(doc->undoStack()->count(), steps + 1);
        EXPECT_EQ(combo->currentIndex(), int(i) + 1);
        EXPECT_TRUE(combo->currentText().startsWith(QString::fromUtf8(preset.name.data())));
        doc->undoStack()->undo();
        EXPECT_EQ(doc->scene(), before);
        // Undo gives the scene its settings back; the target it chose is the
        // editor's, not the scene's, and still rules, so the box names it.
        EXPECT_EQ(combo->currentIndex(), int(i) + 1);
    }
    // Rendering to the settings again, the box shows what they match.
    auto* target = child<QComboBox>("qualityTarget");
    target->setCurrentIndex(0);
    emit target->activated(0);
    EXPECT_EQ(combo->currentIndex(), 0);
}

TEST_F(TradeoffViewTest, Preset_ManualSamplesChange_ShowsCustom) {
    choosePreset(2);  // Preview
    // The samples field takes edits only while the view renders to the settings.
    auto* target = child<QComboBox>("qualityTarget");
    target->setCurrentIndex(0);
    emit target->activated(0);
    auto* combo = child<QComboBox>("renderPreset");
    ASSERT_EQ(combo->currentIndex(), 2);
    EXPECT_EQ(combo->currentText().toStdString(), "Preview (16 spp, depth 5, float)");
    auto* samples = child<QSpinBox>("renderSamples");
    samples->setValue(kRenderPresets[1].samplesPerPixel + 1);
    EXPECT_EQ(doc->scene().render.samplesPerPixel, kRenderPresets[1].samplesPerPixel + 1);
    EXPECT_EQ(combo->currentIndex(), 0);
    EXPECT_EQ(combo->currentText(), QStringLiteral("Custom"));
    samples->setValue(kRenderPresets[1].samplesPerPixel);  // back on the preset
    EXPECT_EQ(combo->currentIndex(), 2);
}

TEST_F(TradeoffViewTest, Predictions_BeforeMeasure_TimeFromTheLastRender_ErrorPointsToMeasure) {
    auto* time = child<QLabel>("predictedTime");
    auto* error = child<QLabel>("predictedError");
    EXPECT_TRUE(time->text().contains(QStringLiteral("measured: the last render")))
        << time->text().toStdString();
    // More samples than any render so far: an estimate, and it says so. Checked
    // before any event runs: the probes' prediction (ProbePredictor) for
    // these settings starts only once the edits pause.
    ASSERT_TRUE(doc->edit(QStringLiteral("spp"), [](Scene& s) { s.render.samplesPerPixel = 8; }));
    EXPECT_TRUE(time->text().contains(QStringLiteral("estimated from the last render")))
        << time->text().toStdString();
    EXPECT_EQ(error->text(), QStringLiteral("Measure gives an error prediction"));
}

// A render's time measures the scene it showed. After a ball is moved, the
// last render at these settings estimates the time, and says so, until the
// view has rendered the moved ball; a change of samples alone keeps the
// renders' times as measurements (checked before any event runs: the new
// render and the probes start only then).
TEST_F(TradeoffViewTest, Predictions_AfterAnEditOfTheScene_TheOldRenderNoLongerMeasures) {
    auto* time = child<QLabel>("predictedTime");
    ASSERT_TRUE(time->text().contains(QStringLiteral("measured: the last render")))
        << time->text().toStdString();
    const std::uint64_t before = doc->contentRevision();
    ASSERT_TRUE(doc->edit(QStringLiteral("spp"), [](Scene& s) { s.render.samplesPerPixel = 8; }));
    EXPECT_EQ(doc->contentRevision(), before);
    ASSERT_TRUE(doc->edit(QStringLiteral("spp"), [](Scene& s) { s.render.samplesPerPixel = 1; }));
    EXPECT_TRUE(time->text().contains(QStringLiteral("measured: the last render")))
        << time->text().toStdString();

    ASSERT_TRUE(doc->edit(QStringLiteral("move"), [](Scene& s) { s.spheres[0].center.x += 0.5; }));
    EXPECT_NE(doc->contentRevision(), before);
    EXPECT_TRUE(time->text().contains(QStringLiteral("estimated from the last render")))
        << time->text().toStdString();
    // Undo brings the ball back, but the revision moves on: the view renders again.
    doc->undoStack()->undo();
    EXPECT_GT(doc->contentRevision(), before + 1);
    // Once the view has rendered the scene as it is, its time measures again.
    EXPECT_TRUE(QTest::qWaitFor(
        [&] { return time->text().contains(QStringLiteral("measured: the last render")); },
        kTimeoutMs))
        << time->text().toStdString();
}

// Once the edits pause, small probe renders predict the
// error, the rays and the time of the settings. The seed's error, checked
// against a converged render; the time only where no render has measured it.
TEST_F(TradeoffViewTest, Predictions_FromProbes_WithinTwoDecibelsOfTheRender) {
    auto* time = child<QLabel>("predictedTime");
    auto* error = child<QLabel>("predictedError");
    ASSERT_TRUE(doc->edit(QStringLiteral("spp"), [](Scene& s) { s.render.samplesPerPixel = 8; }));
    const RenderSettings want = doc->scene().render;
    const auto predictedNow = [&] {
        const ProbePrediction* p = window->renderRecord()->probePrediction();
        return p && p->scene.render == want;
    };
    ASSERT_TRUE(QTest::qWaitFor(predictedNow, kTimeoutMs));
    const RenderPrediction& p = window->renderRecord()->probePrediction()->prediction;
    ASSERT_TRUE(p.predicted) << p.cannot;
    EXPECT_TRUE(error->text().startsWith(QStringLiteral("RMSE %1 of 255, PSNR %2 dB")
                                             .arg(std::sqrt(p.mseCodes2), 0, 'f', 2)
                                             .arg(p.psnrDb, 0, 'f', 1)))
        << error->text().toStdString();
    EXPECT_TRUE(error->text().contains(QStringLiteral("predicted from small probe renders")));
    // Once the view has rendered these settings (on a loaded machine it may
    // still be rendering here), the label's time is measured; before that
    // render (here: after a render at 1 spp, or none), the probes' timed
    // renders give it.
    EXPECT_TRUE(QTest::qWaitFor([&] { return time->text().contains(QStringLiteral("measured")); },
                                kTimeoutMs))
        << time->text().toStdString();
    RenderSettings before = want;
    before.samplesPerPixel = 1;
    for (const std::vector<EditorRender>& renders :
         {std::vector<EditorRender>{{before, 0.1, 1'500'000}}, std::vector<EditorRender>{}}) {
        const Prediction fromProbe = predictSettings(doc->scene(), renders, nullptr, nullptr,
                                                     window->renderRecord()->probePrediction());
        ASSERT_TRUE(fromProbe.seconds.has_value());
        // No view's pace given: the bench scenes' (RenderRecord learns its own).
        EXPECT_DOUBLE_EQ(*fromProbe.seconds,
                         p.seconds + viewExtraSeconds(doc->scene().render, ViewPace{}));
        EXPECT_TRUE(fromProbe.timeSource.contains(
            QStringLiteral("predicted from small timed probe renders: %1 Mrays")
                .arg(p.rays / 1e6, 0, 'f', 1)))
            << fromProbe.timeSource.toStdString();
    }

    if (test::kSanitized) return;  // the numbers, which the Release stage checks
    const FixedCheck rendered = checkFixed(doc->scene(), convergedReference(doc->scene()));
    EXPECT_NEAR(p.psnrDb, rendered.error.psnrSrgb8, 2.0);
    EXPECT_NEAR(p.rays / double(rendered.rays), 1.0, 0.25);
}

// ---------------------------------------------------------------------------
// Pin as Reference

TEST_F(TradeoffViewTest, Pin_DisabledWhileTheRenderIsUnfinished) {
    EXPECT_TRUE(view->pinAction()->isEnabled());
    ASSERT_TRUE(doc->edit(QStringLiteral("spp"), [](Scene& s) { s.render.samplesPerPixel = 2; }));
    // No event has been processed since the edit: its render cannot be complete.
    EXPECT_FALSE(view->pinAction()->isEnabled());
    EXPECT_TRUE(QTest::qWaitFor([&] { return view->pinAction()->isEnabled(); }, kTimeoutMs));
    EXPECT_EQ(log->lastComplete.settings.samplesPerPixel, 2);
}

TEST_F(TradeoffViewTest, Pin_EditChangingSamples_AddsPointWithMeasureErrorOfTheFrames) {
    const RenderFrame pinned = pin();
    ASSERT_TRUE(pinned.linear);
    EXPECT_EQ(view->pinnedImage(), pinned.linear);
    EXPECT_TRUE(view->pinnedPoints().empty());

    QSignalSpy measured(view, &TradeoffView::pointMeasured);
    ASSERT_TRUE(editAndWait([](Scene& s) { s.render.samplesPerPixel = 4; }));
    const RenderFrame after = log->lastComplete;
    ASSERT_TRUE(QTest::qWaitFor([&] { return measured.count() == 1; }, kTimeoutMs));
    ASSERT_EQ(view->pinnedPoints().size(), 1u);
    const PinnedPoint& p = view->pinnedPoints()[0];
    EXPECT_EQ(p.settings.samplesPerPixel, 4);
    EXPECT_EQ(p.generation, after.generation);
    EXPECT_EQ(p.seconds, after.seconds);
    ASSERT_TRUE(p.error.has_value()) << p.note.toStdString();
    const ErrorStats want = measureError(*after.linear, *pinned.linear);
    EXPECT_EQ(p.error->rmseSrgb8, want.rmseSrgb8);
    EXPECT_EQ(p.error->rmseLinear, want.rmseLinear);
    EXPECT_EQ(p.error->psnrSrgb8, want.psnrSrgb8);
    EXPECT_EQ(p.error->largest, want.largest);
    EXPECT_GT(want.rmseSrgb8, 0.0);  // 4 samples against 1: the edges differ

    ASSERT_EQ(view->plot()->spec().points.size(), 1u);
    EXPECT_EQ(view->plot()->spec().points[0].y, want.rmseSrgb8);
    EXPECT_EQ(view->plot()->spec().points[0].x, after.seconds);
    EXPECT_EQ(child<QTableWidget>("pinnedTable")->rowCount(), 1);

    // Its tooltip where it is drawn: the settings and the error.
    const PlotWidget* plot = view->plot();
    ASSERT_TRUE(QTest::qWaitFor([&] { return plot->isVisible(); }, kTimeoutMs));
    const QPointF at = plotLayout(QRectF(plot->rect()), plot->spec(), plot->font())
                           .map(after.seconds, want.rmseSrgb8);
    const QString tip = plot->tooltipAt(at);
    EXPECT_TRUE(tip.startsWith(QStringLiteral("Render 1 against the pinned image: 4 spp, depth 2")))
        << tip.toStdString();
    EXPECT_TRUE(tip.contains(QStringLiteral("%1 of 255").arg(want.rmseSrgb8, 0, 'f', 3)))
        << tip.toStdString();
}

TEST_F(TradeoffViewTest, Pin_SmallerRenderComparedStretched_OtherShapeSkippedWithNote) {
    const RenderFrame pinned = pin();
    QSignalSpy measured(view, &TradeoffView::pointMeasured);
    ASSERT_TRUE(editAndWait([](Scene& s) {
        s.render.width = kWidth / 2;
        s.render.height = kHeight / 2;
    }));
    const RenderFrame half = log->lastComplete;
    ASSERT_TRUE(QTest::qWaitFor([&] { return measured.count() == 1; }, kTimeoutMs));
    ASSERT_TRUE(view->pinnedPoints()[0].error.has_value());
    EXPECT_EQ(view->pinnedPoints()[0].error->rmseSrgb8,
              measureError(*half.linear, *pinned.linear).rmseSrgb8);

    ASSERT_TRUE(editAndWait([](Scene& s) {
        s.render.width = kWidth;
        s.render.height = kWidth;  // square: not a view of the pinned image
    }));
    ASSERT_TRUE(QTest::qWaitFor([&] { return measured.count() == 2; }, kTimeoutMs));
    const PinnedPoint& skipped = view->pinnedPoints()[1];
    EXPECT_FALSE(skipped.error.has_value());
    EXPECT_TRUE(skipped.note.startsWith(QStringLiteral("Not compared")))
        << skipped.note.toStdString();
    EXPECT_EQ(view->plot()->spec().points.size(), 1u);  // the skipped one has no error to plot
}

TEST_F(TradeoffViewTest, Pin_OneSampleImage_WarnsFirst_PinAnywayPinsIt) {
    const RenderFrame shown = log->lastComplete;
    QMessageBox* box = pinNoisy();
    ASSERT_NE(box, nullptr);
    EXPECT_EQ(box->text(),
              QStringLiteral("This image has only 1 sample per pixel: its edges are still jagged, "
                             "and every later render would be scored against that noise instead "
                             "of the true picture.\n\nRender a converged reference at 256 "
                             "samples per pixel (in double precision, in the background) and pin "
                             "it when it is done?"));
    EXPECT_FALSE(view->isPinned()) << "pinned before the user answered";
    click(box, "pinAnywayButton");
    ASSERT_TRUE(view->isPinned());
    EXPECT_EQ(view->pinnedImage(), shown.linear);
    EXPECT_EQ(view->pinnedSettings().samplesPerPixel, 1);
}

TEST_F(TradeoffViewTest, Pin_ManySamples_PinsWithoutAsking) {
    ASSERT_TRUE(
        editAndWait([](Scene& s) { s.render.samplesPerPixel = TradeoffView::kNoisyBelowSamples; }));
    view->pinAction()->trigger();
    EXPECT_TRUE(view->isPinned());
    EXPECT_EQ(window->findChild<QMessageBox*>(QStringLiteral("noisyPinWarning")), nullptr);
}

// The converged reference is core's renderReference at the stated samples, of
// the scene as the view renders it: the pinned image is that, pixel for pixel,
// and the noisy image on screen is scored against it at once.
TEST_F(TradeoffViewTest, Pin_ConvergedReference_PinsARenderAtTheStatedSamples) {
    view->setMeasureGrid(tinyGrid(), 16);  // a 16-sample reference renders in a blink
    const RenderFrame noisy = log->lastComplete;
    QMessageBox* box = pinNoisy();
    ASSERT_NE(box, nullptr);
    EXPECT_TRUE(box->text().contains(QStringLiteral("at 16 samples per pixel")));
    click(box, "renderConvergedButton");
    EXPECT_TRUE(
        child<QLabel>("pinStatus")
            ->text()
            .startsWith(QStringLiteral("Rendering a converged reference at 16 samples per pixel")));
    QSignalSpy measured(view, &TradeoffView::pointMeasured);
    ASSERT_TRUE(QTest::qWaitFor([&] { return view->isPinned(); }, kTimeoutMs));
    const ReferenceRender want = renderReference(doc->scene(), 16);
    EXPECT_EQ(view->pinnedSettings(), want.scene.render);
    EXPECT_EQ(view->pinnedSettings().samplesPerPixel, 16);
    EXPECT_EQ(view->pinnedSettings().precision, Precision::Double);
    EXPECT_EQ(view->pinnedImage()->rgb, want.image.rgb);
    EXPECT_TRUE(child<QLabel>("pinStatus")->text().startsWith(QStringLiteral("Pinned: 16 spp")))
        << child<QLabel>("pinStatus")->text().toStdString();

    ASSERT_TRUE(QTest::qWaitFor([&] { return measured.count() == 1; }, kTimeoutMs));
    const PinnedPoint& p = view->pinnedPoints()[0];
    EXPECT_EQ(p.settings.samplesPerPixel, 1);
    ASSERT_TRUE(p.error.has_value());
    EXPECT_EQ(p.error->rmseSrgb8, measureError(*noisy.linear, want.image).rmseSrgb8);
}

// The converged reference of a scene that is gone is never pinned; Unpin stops it too.
TEST_F(TradeoffViewTest, Pin_ConvergedReference_StoppedBySphereMoveOrUnpin) {
    for (bool byUnpin : {false, true}) {
        SCOPED_TRACE(byUnpin ? "Unpin" : "sphere moved");
        QMessageBox* box = pinNoisy();
        ASSERT_NE(box, nullptr);
        click(box, "renderConvergedButton");
        ASSERT_TRUE(view->isRenderingReference());
        EXPECT_TRUE(view->unpinAction()->isEnabled());  // it cancels the render
        if (byUnpin)
            view->unpinAction()->trigger();
        else
            ASSERT_TRUE(
                doc->edit(QStringLiteral("move"), [](Scene& s) { s.spheres[0].center.x += 0.3; }));
        EXPECT_FALSE(view->isRenderingReference());
        EXPECT_EQ(child<QLabel>("pinStatus")->text(),
                  QStringLiteral("Pin the finished image as a reference to plot every later "
                                 "render's error against it."));
        QTest::qWait(300);  // whatever the stopped render posted arrives, and is dropped
        EXPECT_FALSE(view->isPinned());
        ASSERT_TRUE(QTest::qWaitFor([&] { return view->pinAction()->isEnabled(); }, kTimeoutMs));
    }
}

// The main window goes (its document first) while a converged reference renders
// over an earlier pin: the render stops, nothing reads the document (ASan).
TEST_F(TradeoffViewTest, Pin_ConvergedReference_WindowClosedMeanwhile_StopsCleanly) {
    pin();
    QMessageBox* box = pinNoisy();
    ASSERT_NE(box, nullptr);
    click(box, "renderConvergedButton");
    ASSERT_TRUE(view->isRenderingReference());
    log.reset();
    window.reset();
    SUCCEED();
}

// A sphere moved: the pinned image shows another scene. The dock says so and
// scores nothing until it is pinned again or the move is undone.
TEST_F(TradeoffViewTest, Pin_SphereMoved_MarksThePinStale_NoPointsUntilUndone) {
    pin();
    auto* stale = child<QLabel>("pinStale");
    ASSERT_TRUE(view->isVisible());  // pinning showed the dock
    EXPECT_FALSE(stale->isVisible());

    ASSERT_TRUE(editAndWait([](Scene& s) { s.spheres[0].center.x += 0.3; }));
    EXPECT_TRUE(view->isPinStale());
    EXPECT_TRUE(stale->isVisible());
    EXPECT_EQ(stale->text(), QStringLiteral("The pinned reference is out of date: the scene has "
                                            "changed since it was pinned. Renders are not scored "
                                            "against it until you pin again."));
    // A render-settings change afterwards does not make it current again.
    ASSERT_TRUE(editAndWait([](Scene& s) { s.render.samplesPerPixel = 2; }));
    QTest::qWait(100);  // an error, had one been submitted, would be back by now
    EXPECT_TRUE(view->pinnedPoints().empty());
    EXPECT_TRUE(view->plot()->spec().points.empty());
    EXPECT_EQ(child<QTableWidget>("pinnedTable")->rowCount(), 0);

    // Undo the move (the samples stay at 2): the pinned scene again, scored again.
    QSignalSpy measured(view, &TradeoffView::pointMeasured);
    const int before = log->completed;
    doc->undoStack()->undo();
    doc->undoStack()->undo();
    ASSERT_TRUE(editAndWait([](Scene& s) { s.render.samplesPerPixel = 2; }));
    ASSERT_GT(log->completed, before);
    EXPECT_FALSE(view->isPinStale());
    EXPECT_FALSE(stale->isVisible());
    ASSERT_TRUE(QTest::qWaitFor([&] { return measured.count() >= 1; }, kTimeoutMs));
    EXPECT_EQ(view->pinnedPoints().back().settings.samplesPerPixel, 2);
}

TEST_F(TradeoffViewTest, Unpin_ClearsPointsPlotAndTable_LaterRendersAddNothing) {
    pin();
    QSignalSpy measured(view, &TradeoffView::pointMeasured);
    ASSERT_TRUE(editAndWait([](Scene& s) { s.render.samplesPerPixel = 2; }));
    ASSERT_TRUE(QTest::qWaitFor([&] { return measured.count() == 1; }, kTimeoutMs));
    ASSERT_EQ(view->plot()->spec().points.size(), 1u);

    ASSERT_TRUE(view->unpinAction()->isEnabled());
    view->unpinAction()->trigger();
    EXPECT_FALSE(view->isPinned());
    EXPECT_FALSE(view->unpinAction()->isEnabled());
    EXPECT_TRUE(view->pinnedPoints().empty());
    EXPECT_TRUE(view->plot()->spec().points.empty());
    EXPECT_EQ(child<QTableWidget>("pinnedTable")->rowCount(), 0);

    ASSERT_TRUE(editAndWait([](Scene& s) { s.render.samplesPerPixel = 4; }));
    QTest::qWait(100);
    EXPECT_TRUE(view->pinnedPoints().empty());
}

TEST_F(TradeoffViewTest, OpeningAScene_UnpinsAndForgetsTheRecord) {
    pin();
    ASSERT_FALSE(window->renderRecord()->renders().empty());
    open(kWidth, kHeight);
    EXPECT_FALSE(view->isPinned());
    // Only the new scene's first render is remembered.
    EXPECT_EQ(window->renderRecord()->renders().size(), 1u);
}

// Every column of `table` as wide as its title and its widest cell need, with
// the style's margins: no text is elided ("Time (…").
void expectColumnsFitTheirContents(const QTableWidget* table, bool allInView) {
    const QHeaderView* header = table->horizontalHeader();
    QStyle* style = table->style();
    const int headerMargins = 2 * style->pixelMetric(QStyle::PM_HeaderMargin, nullptr, header);
    const int cellMargins =
        2 * (style->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, table) + 1);
    for (int c = 0; c < table->columnCount(); ++c) {
        const QString title = table->horizontalHeaderItem(c)->text();
        const int width = header->sectionSize(c);
        for (const QString& line : title.split(QLatin1Char('\n')))
            EXPECT_GE(width, header->fontMetrics().horizontalAdvance(line) + headerMargins)
                << table->objectName().toStdString() << ": " << title.toStdString();
        // Whole inside the table's visible part: nothing cut off at its right edge.
        if (allInView) {
            EXPECT_LE(header->sectionViewportPosition(c) + width, table->viewport()->width())
                << table->objectName().toStdString() << ": " << title.toStdString();
        }
        for (int r = 0; r < table->rowCount(); ++r) {
            const QString cell = table->item(r, c)->text();
            EXPECT_GE(width, table->fontMetrics().horizontalAdvance(cell) + cellMargins)
                << title.toStdString() << ", row " << r << ": " << cell.toStdString();
        }
    }
}

// In the default window the dock is too narrow for the plot and the table side
// by side: the plot becomes a tab of its own and each table has the dock's
// whole width (about 660 px: the last columns still scroll into view). In a
// wider one, the table sits beside the plot with every column in view.
TEST_F(TradeoffViewTest, Tables_ColumnsAsWideAsTheirTitlesAndCellsAndAllInView) {
    pin();
    QSignalSpy measured(view, &TradeoffView::pointMeasured);
    ASSERT_TRUE(editAndWait([](Scene& s) { s.render.samplesPerPixel = 4; }));
    ASSERT_TRUE(QTest::qWaitFor([&] { return measured.count() == 1; }, kTimeoutMs));
    auto* pinned = child<QTableWidget>("pinnedTable");
    auto* measureTable = child<QTableWidget>("measureTable");
    ASSERT_EQ(pinned->rowCount(), 1);
    auto* tabs = qobject_cast<QTabWidget*>(pinned->parentWidget()->parentWidget());
    ASSERT_NE(tabs, nullptr);
    const QWidget* plot = view->plot();
    for (int windowWidth : {1400, 2300}) {
        SCOPED_TRACE(windowWidth);
        window->resize(windowWidth, 900);
        QTest::qWait(50);  // the dock and the split follow
        const bool beside = windowWidth == 2300;
        EXPECT_EQ(tabs->tabText(0), beside ? QStringLiteral("Pinned") : QStringLiteral("Plot"));
        for (QTableWidget* table : {pinned, measureTable}) {
            tabs->setCurrentWidget(table);  // as a click on its tab does
            QTest::qWait(50);
            EXPECT_EQ(plot->isVisible(), beside);
            if (!beside) {
                EXPECT_GE(table->width(), view->width() - 40);  // the dock's whole width
            }
            expectColumnsFitTheirContents(table, beside);
        }
    }
}

// ---------------------------------------------------------------------------
// Measure

TEST_F(TradeoffViewTest, Measure_ActionAsksFirst_CancelStartsNothing) {
    view->measureAction()->trigger();
    auto* box = window->findChild<QMessageBox*>(QStringLiteral("measureConfirm"));
    ASSERT_NE(box, nullptr);
    EXPECT_TRUE(box->isVisible());
    EXPECT_TRUE(box->text().contains(QStringLiteral("about a minute")))
        << box->text().toStdString();
    EXPECT_TRUE(box->text().contains(QStringLiteral("252 settings"))) << box->text().toStdString();
    box->reject();
    EXPECT_FALSE(view->isMeasuring());
}

TEST_F(TradeoffViewTest, Measure_TinyScene_FillsPlotAndTableWithEveryPointAndAFront) {
    open(64, 48);
    const TradeoffGrid grid = tinyGrid();
    ASSERT_TRUE(measure(grid, 16));
    const auto& points = view->measurePoints();
    ASSERT_EQ(int(points.size()), gridPointCount(grid));
    const auto front = std::count_if(points.begin(), points.end(),
                                     [](const TradeoffPoint& p) { return p.pareto; });
    EXPECT_GT(front, 0);
    const MeasureResults* m = window->renderRecord()->measure();
    ASSERT_NE(m, nullptr);
    EXPECT_FALSE(m->cancelled);
    EXPECT_EQ(m->total, gridPointCount(grid));
    EXPECT_EQ(m->referenceSamples, 16);

    // Every point on the plot (none equals the 16-sample reference), the front ringed.
    const PlotSpec& spec = view->plot()->spec();
    EXPECT_EQ(spec.points.size(), points.size());
    EXPECT_EQ(std::count_if(spec.points.begin(), spec.points.end(),
                            [](const PlotPoint& p) { return p.highlighted; }),
              front);
    EXPECT_EQ(child<QTableWidget>("measureTable")->rowCount(), int(points.size()));
    EXPECT_FALSE(child<QProgressBar>("measureProgress")->isVisible());
    EXPECT_TRUE(view->measureAction()->isEnabled());
}

TEST_F(TradeoffViewTest, Measure_Cancel_StopsWithinAShortTimeAndKeepsPartialResults) {
    const TradeoffGrid grid = slowGrid();
    view->setMeasureGrid(grid, 16);
    QSignalSpy progress(view, &TradeoffView::measureProgress);
    QSignalSpy finished(view, &TradeoffView::measureFinished);
    ASSERT_TRUE(view->startMeasure());
    ASSERT_TRUE(view->isMeasuring());
    ASSERT_TRUE(QTest::qWaitFor([&] { return progress.count() >= 3; }, kTimeoutMs));
    ASSERT_TRUE(view->cancelMeasureAction()->isEnabled());
    QElapsedTimer clock;
    clock.start();
    view->cancelMeasureAction()->trigger();
    ASSERT_TRUE(finished.wait(kTimeoutMs));
    // A point at 160 x 120 takes milliseconds; the stop is asked every tile row.
    EXPECT_LT(clock.elapsed(), 2000);
    EXPECT_TRUE(finished.at(0).at(0).toBool());
    const MeasureResults* m = window->renderRecord()->measure();
    ASSERT_NE(m, nullptr);
    EXPECT_TRUE(m->cancelled);
    EXPECT_GE(m->points.size(), 3u);
    EXPECT_LT(int(m->points.size()), gridPointCount(grid));
    EXPECT_EQ(view->measurePoints().size(), m->points.size());
    EXPECT_EQ(view->plot()->spec().points.size(), m->points.size());
    EXPECT_TRUE(child<QLabel>("measureStatus")->text().contains(QStringLiteral("Cancelled")));
    EXPECT_FALSE(view->isMeasuring());
}

TEST_F(TradeoffViewTest, Measure_OpeningASceneMeanwhile_StopsItAndKeepsNothing) {
    view->setMeasureGrid(slowGrid(), 16);
    QSignalSpy progress(view, &TradeoffView::measureProgress);
    QSignalSpy finished(view, &TradeoffView::measureFinished);
    ASSERT_TRUE(view->startMeasure());
    ASSERT_TRUE(QTest::qWaitFor([&] { return progress.count() >= 1; }, kTimeoutMs));
    open(kWidth, kHeight);
    EXPECT_FALSE(view->isMeasuring());
    QTest::qWait(100);  // anything the stopped run had posted arrives, and is dropped
    EXPECT_EQ(finished.count(), 0);
    EXPECT_TRUE(view->measurePoints().empty());
    EXPECT_EQ(window->renderRecord()->measure(), nullptr);
    EXPECT_TRUE(view->measureAction()->isEnabled());
}

TEST_F(TradeoffViewTest, Measure_ThenPredictions_ShowMeasuredAndInterpolatedValues) {
    open(64, 48);
    ASSERT_TRUE(measure(tinyGrid(), 16));
    const MeasureResults* m = window->renderRecord()->measure();
    ASSERT_NE(m, nullptr);
    auto pointAt = [&](int spp) -> const TradeoffPoint& {
        const RenderSettings& r = doc->scene().render;
        for (const TradeoffPoint& p : m->points)
            if (p.settings.samplesPerPixel == spp && p.settings.maxDepth == r.maxDepth &&
                p.settings.precision == r.precision)
                return p;
        ADD_FAILURE() << "no point at " << spp << " spp";
        return m->points.front();
    };
    auto* time = child<QLabel>("predictedTime");
    auto* error = child<QLabel>("predictedError");
    // The seed's own settings (1 spp, depth 2, float) are a grid point.
    const TradeoffPoint& own = pointAt(1);
    EXPECT_TRUE(error->text().startsWith(
        QStringLiteral("RMSE %1 of 255").arg(own.error.rmseSrgb8, 0, 'f', 2)))
        << error->text().toStdString();
    EXPECT_TRUE(error->text().contains(QStringLiteral("measured by Measure")));
    EXPECT_TRUE(time->text().contains(QStringLiteral("measured by Measure")));

    // Between two grid points: interpolated, and said so.
    ASSERT_TRUE(doc->edit(QStringLiteral("spp"), [](Scene& s) { s.render.samplesPerPixel = 3; }));
    EXPECT_TRUE(error->text().contains(QStringLiteral("interpolated from Measure between 2 and 4")))
        << error->text().toStdString();
    // Beyond the grid: no error, and the reason.
    ASSERT_TRUE(doc->edit(QStringLiteral("spp"), [](Scene& s) { s.render.samplesPerPixel = 16; }));
    EXPECT_TRUE(error->text().startsWith(QStringLiteral("outside Measure's grid")))
        << error->text().toStdString();
    // Another scene content: Measure no longer speaks for it.
    ASSERT_TRUE(doc->edit(QStringLiteral("move"), [](Scene& s) { s.spheres[0].center.x += 0.1; }));
    EXPECT_TRUE(error->text().contains(QStringLiteral("the scene changed since Measure")))
        << error->text().toStdString();
}

// ---------------------------------------------------------------------------
// predictSettings on its own

TEST(SettingsPrediction, TimeScalesWithPixelsTimesSamplesAtTheSameDepthAndPrecision) {
    Scene scene;
    scene.render = {640, 480, 2, 1, Precision::Float};
    std::vector<EditorRender> renders{{{320, 240, 2, 4, Precision::Float}, 0.5, 1000000}};
    const Prediction p = predictSettings(scene, renders, nullptr);
    ASSERT_TRUE(p.seconds.has_value());
    EXPECT_DOUBLE_EQ(*p.seconds, 0.5);  // 4x the pixels, a quarter of the samples
    EXPECT_TRUE(p.timeSource.startsWith(QStringLiteral("estimated from the last render at")));
    EXPECT_FALSE(p.rmseSrgb8.has_value());

    scene.render.maxDepth = 5;  // no render at this depth: rough, and said so
    const Prediction rough = predictSettings(scene, renders, nullptr);
    EXPECT_TRUE(rough.timeSource.startsWith(QStringLiteral("rough estimate")));
}

TEST(SettingsPrediction, ErrorInterpolatedLogLogBetweenSampleCounts) {
    Scene scene;
    scene.render = {100, 100, 3, 4, Precision::Double};
    MeasureResults m;
    m.scene = scene;
    for (int spp : {2, 8}) {
        TradeoffPoint p;
        p.settings = {spp, 3, Precision::Double, 1.0};
        p.width = p.height = 100;
        p.seconds = spp * 0.1;
        p.error.rmseSrgb8 = spp == 2 ? 8.0 : 2.0;
        m.points.push_back(p);
    }
    const Prediction p = predictSettings(scene, {}, &m);
    ASSERT_TRUE(p.rmseSrgb8.has_value());
    EXPECT_NEAR(*p.rmseSrgb8, 4.0, 1e-12);  // half-way in log spp: the geometric mean
    ASSERT_TRUE(p.seconds.has_value());
    EXPECT_NEAR(*p.seconds, 0.4, 1e-12);  // linear in spp
    EXPECT_TRUE(p.errorSource.startsWith(QStringLiteral("interpolated")));
}

// The view's pace: what its renders took beyond the probes' one-pass
// prediction of the very same scene, a pixel and a pass, learnt in the
// editor; its median prices the passes of the Render tab's probe time.
TEST(RenderRecord, ViewPace_IsTheMedianOfWhatItsRendersTookBeyondTheProbes) {
    RenderRecord record;
    Scene scene = test::seedScene(640, 480);
    scene.render.samplesPerPixel = 8;
    // The preview, then 1, 1, 2 and 4 samples.
    ASSERT_EQ(passCount(scene.render), 5);
    const double pixelPasses = 640.0 * 480.0 * 5;
    auto probe = std::make_shared<ProbePrediction>();
    probe->scene = scene;
    probe->prediction.predicted = true;
    probe->prediction.seconds = 0.2;
    probe->prediction.rays = 4e6;
    EXPECT_DOUBLE_EQ(record.viewPace().secondsAPixelPass, kUnmeasuredSecondsAPixelPass);
    Prediction p = predictSettings(scene, {}, nullptr, nullptr, probe.get(), record.viewPace());
    ASSERT_TRUE(p.seconds.has_value());
    EXPECT_DOUBLE_EQ(*p.seconds, 0.2 + kUnmeasuredSecondsAPixelPass * pixelPasses);
    EXPECT_TRUE(p.timeSource.endsWith(QStringLiteral(
        "and about 0.034 s for the view's 5 passes and frames (not yet measured here)")))
        << p.timeSource.toStdString();

    // The first render shares the cores with the window's first showing: no pace.
    probe->contentRevision = 7;
    record.addViewRender(7, scene.render, 0.9);
    record.setProbePrediction(probe);
    EXPECT_EQ(record.viewPace().renders, 0);
    // Rendered after the prediction, or before it: either pairs them, once.
    record.addViewRender(7, scene.render, 0.25);
    EXPECT_EQ(record.viewPace().renders, 1);
    EXPECT_DOUBLE_EQ(record.viewPace().secondsAPixelPass, 0.05 / pixelPasses);
    record.setProbePrediction(probe);
    EXPECT_EQ(record.viewPace().renders, 1);
    // Another scene's render (the document's next revision), or other
    // settings: not what the probes predicted.
    record.addViewRender(8, scene.render, 0.9);
    Scene more = scene;
    more.render.samplesPerPixel = 16;
    record.addViewRender(7, more.render, 0.9);
    EXPECT_EQ(record.viewPace().renders, 1);

    p = record.predict(scene);
    ASSERT_TRUE(p.seconds.has_value());
    EXPECT_DOUBLE_EQ(*p.seconds, 0.25);
    EXPECT_TRUE(p.timeSource.endsWith(
        QStringLiteral("and 0.05 s for the view's 5 passes and frames (as its last render)")))
        << p.timeSource.toStdString();
    // 256 samples make 10 passes: twice the time beyond one pass.
    more.render.samplesPerPixel = 256;
    EXPECT_DOUBLE_EQ(viewExtraSeconds(more.render, record.viewPace()), 0.1);

    // The median of the last five: the first (0.05 s) has gone.
    for (double extra : {0.0, 0.09, 0.01, 0.03, 0.02}) {
        record.addViewRender(7, scene.render, 0.2 + extra);
        record.setProbePrediction(probe);
    }
    EXPECT_EQ(record.viewPace().renders, 5);
    EXPECT_NEAR(record.viewPace().secondsAPixelPass * pixelPasses, 0.02, 1e-12);
    // Renders quicker than predicted: the passes priced at nothing, not less.
    for (int i = 0; i < 3; ++i) {
        record.addViewRender(7, scene.render, 0.15);
        record.setProbePrediction(probe);
    }
    EXPECT_EQ(record.viewPace().secondsAPixelPass, 0.0);
}

}  // namespace
}  // namespace whitted::ui
