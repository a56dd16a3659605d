// The presets in the editor render to their quality. A preset's
// shortcut makes its target the one the view renders to; each render chooses
// its depth for the scene and samples until the estimate is under the target,
// and the status bar says what it chose and reached. "Render to" in the
// Render tab goes back to the scene's own samples and depth; Export renders
// to the target it is given. Measured against a converged render of the same
// scene (double, 512 samples a pixel, depth 14).
#include <QComboBox>
#include <QLabel>
#include <QRegularExpression>
#include <QSpinBox>
#include <QStatusBar>
#include <QTest>

#include <cmath>

#include "analysis/quality_check.h"
#include "analysis/target_prediction.h"
#include "document/quality_choice.h"
#include "document/settings_words.h"
#include "editor/main_window.h"
#include "image/image_error.h"
#include "image/image_io.h"
#include "panels/preset_controls.h"
#include "prediction/render_record.h"
#include "support/export_support.h"
#include "support/main_window_fixture.h"
#include "support/test_support.h"

namespace whitted::ui {
namespace {

class QualityEditorTest : public MainWindowTest {
  protected:
    // The status bar's labels, joined: what a user reads there.
    QString statusText() const {
        QStringList texts;
        for (const QLabel* l : window->statusBar()->findChildren<QLabel*>()) texts << l->text();
        return texts.join(QStringLiteral(" | "));
    }

    // Presses `keys` and waits for the complete frame of the render they start.
    ::testing::AssertionResult pressAndWait(const char* keys) {
        const int before = log->completed;
        QTest::keySequence(window.get(), QKeySequence(QString::fromLatin1(keys)));
        return waitForRender(before);
    }
};

TEST_F(QualityEditorTest, FinalShortcut_RendersToFinalsTarget_MeasuredAgainstAConvergedRender) {
    QStringList duringTheRender;  // the status bar at each pass before the last
    QObject::connect(window.get(), &MainWindow::frameShown, window.get(),
                     [&](const RenderFrame& f) {
                         if (f.qualityPlan && !f.renderComplete && !f.preview)
                             duringTheRender << statusText();
                     });
    // The preset's tooltip, where a user hovers before choosing Final.
    auto finalTip = [&] {
        return child<QComboBox>("renderPreset")->itemData(3, Qt::ToolTipRole).toString();
    };
    EXPECT_TRUE(finalTip().startsWith(
        QStringLiteral("Renders to Final: 50 dB, no pixel off by more than 16 codes")))
        << finalTip().toStdString();
    EXPECT_TRUE(finalTip().contains(QStringLiteral("Not yet rendered to it on this scene")))
        << finalTip().toStdString();
    ASSERT_TRUE(pressAndWait("Ctrl+3"));
    ASSERT_TRUE(window->qualityChoice()->target().has_value());
    EXPECT_EQ(window->qualityChoice()->target()->name, "Final");
    EXPECT_EQ(child<QComboBox>("qualityTarget")->currentIndex(), 3);  // after the settings
    // The Preset box names the target that rules, not the samples and depth it wrote.
    EXPECT_EQ(child<QComboBox>("renderPreset")->currentText().toStdString(),
              "Final: 50 dB, no pixel off by more than 16 codes");
    const RenderFrame& frame = log->lastComplete;
    ASSERT_TRUE(frame.qualityPlan && frame.qualityReached && frame.linear);

    if (!test::kSanitized) {  // the numbers, which the Release stage checks
        const ErrorStats error = measureError(*frame.linear, convergedReference(doc->scene()));
        EXPECT_GE(error.psnrSrgb8, 50.0);
        EXPECT_LE(error.largest, 16.0);
    }
    // Sampled where the picture needs it, not everywhere alike.
    EXPECT_LT(frame.qualityReached->fewestSamples, frame.qualityReached->mostSamples);
    EXPECT_EQ(frame.settings.maxDepth, frame.qualityPlan->maxDepth);

    const QString status = statusText();
    EXPECT_TRUE(
        status.contains(QStringLiteral("Final, depth %1: about ").arg(frame.qualityPlan->maxDepth)))
        << status.toStdString();
    EXPECT_TRUE(status.contains(QStringLiteral(" dB"))) << status.toStdString();
    EXPECT_TRUE(status.contains(QStringLiteral("%1 to %2 samples per pixel")
                                    .arg(frame.qualityReached->fewestSamples)
                                    .arg(frame.qualityReached->mostSamples)))
        << status.toStdString();
    // The tooltip now says what that render took.
    EXPECT_TRUE(finalTip().contains(
        QStringLiteral(
            "The last render to it here: %1 s, depth %2, %3 to %4 samples per pixel, about ")
            .arg(frame.seconds, 0, 'f', 2)
            .arg(frame.qualityPlan->maxDepth)
            .arg(frame.qualityReached->fewestSamples)
            .arg(frame.qualityReached->mostSamples)))
        << finalTip().toStdString();
    // Its passes are counted, but no total is promised: each pass decides
    // whether another follows.
    ASSERT_FALSE(duringTheRender.isEmpty());
    for (const QString& text : duringTheRender) {
        EXPECT_TRUE(text.contains(
            QStringLiteral("Final, depth %1: Pass ").arg(frame.qualityPlan->maxDepth)))
            << text.toStdString();
        EXPECT_FALSE(text.contains(QRegularExpression(QStringLiteral("Pass \\d+ of"))))
            << text.toStdString();
    }
    // Depth and samples are the target's to choose: their fields rest, and
    // say beside the settings' numbers that the render does not use them.
    for (const char* name : {"renderMaxDepth", "renderSamples"}) {
        auto* field = child<QSpinBox>(name);
        EXPECT_FALSE(field->isEnabled()) << name;
        EXPECT_EQ(field->text(),
                  QStringLiteral("%1  (not used while rendering to Final)").arg(field->value()))
            << name;
    }
    EXPECT_EQ(child<QSpinBox>("renderMaxDepth")->value(), doc->scene().render.maxDepth);
    // The predictions are for settings: with a target the Render tab says so.
    const QString predicted = child<QLabel>("predictedTime")->text();
    EXPECT_TRUE(predicted.startsWith(QStringLiteral("not predicted"))) << predicted.toStdString();
    EXPECT_TRUE(predicted.contains(QStringLiteral("the last one here took %1 s, depth %2")
                                       .arg(frame.seconds, 0, 'f', 2)
                                       .arg(frame.qualityPlan->maxDepth)))
        << predicted.toStdString();
}

// Before a render to a target, the Render tab predicts it from the probes:
// the plan the render then makes and its samples from a quarter of the
// picture's tiles rendered to the target (core/analysis/target_prediction.h).
// A picture of the fixture's 160x120 is rendered as fast as it is predicted.
TEST_F(QualityEditorTest, RenderTab_PredictsARenderToTheTarget_TheDepthAndSamplesItThenTakes) {
    const auto predictedFor = [&](const QualityTarget& target) {
        return window->renderRecord()->targetPrediction(doc->scene(), target);
    };
    ASSERT_TRUE(pressAndWait("Ctrl+2"));
    ASSERT_TRUE(QTest::qWaitFor([&] { return predictedFor(previewQuality()); }, 30000));
    auto* time = child<QLabel>("predictedTime");
    EXPECT_TRUE(time->text().startsWith(QStringLiteral(
        "not predicted: a picture this small is rendered as fast as it is predicted")))
        << time->text().toStdString();

    ASSERT_TRUE(editAndWait([](Scene& s) {
        s.render.width = 320;
        s.render.height = 240;
    }));
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
            const TargetPrediction* p = predictedFor(previewQuality());
            return p && p->predicted;
        },
        30000));
    const TargetPrediction& p = *predictedFor(previewQuality());
    const RenderFrame& frame = log->lastComplete;
    ASSERT_TRUE(frame.qualityPlan && frame.qualityReached);
    EXPECT_EQ(p.plan.maxDepth, frame.qualityPlan->maxDepth);
    // Planned once between them (PlanMemo): the same planning's CPU time.
    EXPECT_EQ(p.plan.cpuSeconds, frame.qualityPlan->cpuSeconds);
    EXPECT_NEAR(p.meanSamples / frame.qualityReached->meanSamples, 1.0, 0.25);
    EXPECT_TRUE(time->text().startsWith(QStringLiteral("about "))) << time->text().toStdString();
    EXPECT_TRUE(time->text().contains(QStringLiteral(": depth %1, %2 samples per pixel on average")
                                          .arg(frame.qualityPlan->maxDepth)
                                          .arg(p.meanSamples, 0, 'f', 1)))
        << time->text().toStdString();
    const QString error = child<QLabel>("predictedError")->text();
    EXPECT_TRUE(error.startsWith(
        QStringLiteral("about %1 dB, no pixel off by more than about ").arg(p.psnrDb, 0, 'f', 1)))
        << error.toStdString();
}

// The presets not chosen are predicted too, for their tooltips: before
// choosing Final a user reads what a render to it will take, and the view's
// render to Final then starts from the plan that prediction made.
TEST_F(QualityEditorTest, PresetTooltip_PredictsATargetNotChosen_ChoosingItKeepsThePlan) {
    ASSERT_TRUE(pressAndWait("Ctrl+2"));
    // Just over the size a prediction renders whole, and time to wait: at
    // 320x240 the render to Final took 13 s under ThreadSanitizer alone (6 s
    // at this size), and over 20 s beside other tests.
    renderTimeoutMs = 3 * kRenderTimeoutMs;
    ASSERT_TRUE(editAndWait([](Scene& s) {
        s.render.width = 192;
        s.render.height = 144;
    }));
    const auto finalPredicted = [&] {
        return window->renderRecord()->targetPrediction(doc->scene(), finalQuality());
    };
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
            const TargetPrediction* p = finalPredicted();
            return p && p->predicted;
        },
        60000));
    const TargetPrediction ahead = *finalPredicted();
    const QString tip = child<QComboBox>("renderPreset")->itemData(3, Qt::ToolTipRole).toString();
    EXPECT_TRUE(
        tip.contains(QStringLiteral("\nTime: about %1 (%2 of it choosing the settings)")
                         .arg(secondsText(ahead.seconds()), secondsText(ahead.planSeconds))))
        << tip.toStdString();
    EXPECT_TRUE(tip.contains(QStringLiteral(": depth %1, %2 samples per pixel on average")
                                 .arg(ahead.plan.maxDepth)
                                 .arg(ahead.meanSamples, 0, 'f', 1)))
        << tip.toStdString();
    EXPECT_TRUE(
        tip.contains(QStringLiteral("\nError: about %1 dB, no pixel off by more than about ")
                         .arg(ahead.psnrDb, 0, 'f', 1)))
        << tip.toStdString();

    ASSERT_TRUE(pressAndWait("Ctrl+3"));  // sets Final's samples and depth as well
    const RenderFrame& frame = log->lastComplete;
    ASSERT_TRUE(frame.qualityPlan && frame.qualityReached);
    EXPECT_EQ(frame.qualityPlan->cpuSeconds, ahead.plan.cpuSeconds);  // the same planning
    EXPECT_EQ(frame.qualityPlan->maxDepth, ahead.plan.maxDepth);
    EXPECT_NEAR(ahead.meanSamples / frame.qualityReached->meanSamples, 1.0, 0.25);
    // The Render tab predicts the render to Final, though its samples and depth changed.
    EXPECT_TRUE(child<QLabel>("predictedTime")->text().startsWith(QStringLiteral("about ")))
        << child<QLabel>("predictedTime")->text().toStdString();
}

// With a target chosen, the scene's own settings are predicted too: the
// item of "Render to" that goes back to them, and the preset whose settings
// they are, say what a render with them takes before the user chooses it.
TEST_F(QualityEditorTest, RenderToTooltip_WithATargetChosen_PredictsTheScenesOwnSettingsToo) {
    // Preview: 16 spp, depth 5, float, and its target. The fixture's 160x120
    // is large enough for the probes to predict (render_prediction.h).
    ASSERT_TRUE(pressAndWait("Ctrl+2"));
    ASSERT_EQ(window->qualityChoice()->target(), previewQuality());
    const Scene scene = doc->scene();
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
            const ProbePrediction* p = window->renderRecord()->probePrediction();
            return p && p->scene == scene;
        },
        60000));
    const RenderPrediction& p = window->renderRecord()->probePrediction()->prediction;
    ASSERT_TRUE(p.predicted) << p.cannot;
    const QString time = QStringLiteral("\nTime: %1")
                             .arg(PresetControls::timeText(window->renderRecord()->predict(scene)));
    EXPECT_TRUE(time.contains(QStringLiteral("predicted from small timed probe renders: %1 Mrays")
                                  .arg(p.rays / 1e6, 0, 'f', 1)))
        << time.toStdString();
    const QString error = QStringLiteral("\nError: RMSE %1 of 255, PSNR %2 dB")
                              .arg(std::sqrt(p.mseCodes2), 0, 'f', 2)
                              .arg(p.psnrDb, 0, 'f', 1);

    const QString renderTo =
        child<QComboBox>("qualityTarget")->itemData(0, Qt::ToolTipRole).toString();
    EXPECT_TRUE(renderTo.startsWith(
        QStringLiteral("Renders 16 samples per pixel to max depth 5 in float, as set here.")))
        << renderTo.toStdString();
    EXPECT_TRUE(renderTo.contains(time)) << renderTo.toStdString();
    EXPECT_TRUE(renderTo.contains(error)) << renderTo.toStdString();
    const QString preview =
        child<QComboBox>("renderPreset")->itemData(2, Qt::ToolTipRole).toString();
    EXPECT_TRUE(preview.contains(QStringLiteral("max depth set here:") + time))
        << preview.toStdString();
    EXPECT_TRUE(preview.contains(error)) << preview.toStdString();
}

// The status bar and the export message: a range where tiles stopped at
// different counts, one count where all stopped at it (Draft's centres).
TEST(QualityChoiceText, SamplesTaken_ARangeOrOneCount) {
    AdaptiveOutcome reached;
    reached.fewestSamples = 2;
    reached.mostSamples = 64;
    EXPECT_EQ(QualityChoice::samplesTaken(reached), QStringLiteral("2 to 64 samples per pixel"));
    reached.fewestSamples = reached.mostSamples = 1;
    EXPECT_EQ(QualityChoice::samplesTaken(reached), QStringLiteral("1 sample per pixel"));
    reached.fewestSamples = reached.mostSamples = 16;
    EXPECT_EQ(QualityChoice::samplesTaken(reached), QStringLiteral("16 samples per pixel"));
}

TEST_F(QualityEditorTest, RenderToTheSettings_AfterATarget_RendersTheScenesSamplesAgain) {
    ASSERT_TRUE(pressAndWait("Ctrl+1"));
    ASSERT_TRUE(log->lastComplete.qualityPlan);
    EXPECT_EQ(log->lastComplete.qualityPlan->target.name, "Draft");

    auto* target = child<QComboBox>("qualityTarget");
    const int before = log->completed;
    target->setCurrentIndex(0);
    emit target->activated(0);  // as a user's choice arrives
    ASSERT_TRUE(waitForRender(before));
    EXPECT_FALSE(window->qualityChoice()->target().has_value());
    EXPECT_TRUE(child<QWidget>("renderMaxDepth")->isEnabled());
    EXPECT_TRUE(child<QWidget>("renderSamples")->isEnabled());
    // The presets are settings again: the box shows the one Ctrl+1 wrote.
    EXPECT_EQ(child<QComboBox>("renderPreset")->currentText().toStdString(),
              "Draft (1 spp, depth 2, float)");
    EXPECT_EQ(child<QSpinBox>("renderSamples")->text(),
              QString::number(doc->scene().render.samplesPerPixel));
    const RenderFrame& frame = log->lastComplete;
    EXPECT_FALSE(frame.qualityPlan);
    EXPECT_EQ(frame.samples, doc->scene().render.samplesPerPixel);  // Draft's: 1
    EXPECT_TRUE(statusText().contains(QStringLiteral("| 1 sample per pixel |")))
        << statusText().toStdString();
    EXPECT_EQ(frame.settings.maxDepth, doc->scene().render.maxDepth);
    // The same pixels as a fixed render of the scene: nothing of the target is left.
    EXPECT_TRUE(sameImage(frame.image, coreRender(doc->scene())));
}

TEST_F(QualityEditorTest, ExportToPreview_WritesAFileThatMeetsIt_AndSaysWhatItReached) {
    ExportDialog dialog(doc->scene(), previewQuality(), QString::fromStdString(dir.path().string()),
                        QStringLiteral("preview"));
    auto* quality = dialog.findChild<QComboBox*>(QStringLiteral("exportQuality"));
    ASSERT_NE(quality, nullptr);
    EXPECT_EQ(quality->currentIndex(), 2);  // the editor's target is the dialog's first choice
    EXPECT_FALSE(dialog.findChild<QWidget*>(QStringLiteral("exportSamples"))->isEnabled());
    ExportSettings settings = dialog.settings();
    ASSERT_TRUE(settings.quality.has_value());

    const ExportOutcome exported = exportAndWait(doc->scene(), settings, kRenderTimeoutMs);
    ASSERT_TRUE(exported.finished);
    const QString& message = exported.message;
    ASSERT_TRUE(exported.ok) << message.toStdString();
    EXPECT_TRUE(message.contains(QStringLiteral("Preview: 35 dB"))) << message.toStdString();
    EXPECT_TRUE(message.contains(QStringLiteral("samples per pixel, about ")))
        << message.toStdString();

    const Image written = readImage(dir.path() / "preview.png");
    if (test::kSanitized) return;  // the numbers, which the Release stage checks
    const ErrorStats error = measureError(written, convergedReference(doc->scene()));
    EXPECT_GE(error.psnrSrgb8, 35.0);
    EXPECT_LE(error.largest, 64.0);
}

}  // namespace
}  // namespace whitted::ui
