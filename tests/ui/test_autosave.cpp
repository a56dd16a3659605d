// Crash recovery: edits are copied to a recovery file after each
// burst, the copy goes away when the scene is saved or the editor exits
// normally, and after the editor is killed with SIGKILL the next start offers
// the copy back.
#include <gtest/gtest.h>

#include <QApplication>
#include <QMessageBox>
#include <QProcess>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>
#include <QUndoStack>

#include <filesystem>

#include "document/autosave.h"
#include "editor/main_window.h"
#include "scene/scene_io.h"
#include "support/core_support.h"
#include "support/test_support.h"

namespace whitted::ui {
namespace {

namespace fs = std::filesystem;

class AutosaveTest : public ::testing::Test {
  protected:
    void SetUp() override {
        recoveryDir = QString::fromStdString((dir / "recovery").string());
        qputenv("WHITTED_RECOVERY_DIR", recoveryDir.toLocal8Bit());
        original = test::seedScene(64, 48);
        scenePath = QString::fromStdString(test::saveSceneIn(dir, original));
    }
    void TearDown() override { qunsetenv("WHITTED_RECOVERY_DIR"); }

    std::vector<std::string> recoveryFiles() const {
        return test::directoryEntries(recoveryDir.toStdString());
    }

    // One edit (the first sphere's radius to 0.25), then its recovery copy written.
    static ::testing::AssertionResult editAndWaitForCopy(MainWindow& window) {
        window.autosave()->setDelay(50);
        QSignalSpy written(window.autosave(), &Autosave::written);
        window.document()->edit("edit", [](Scene& s) { s.spheres[0].radius = 0.25; });
        if (written.wait(5000)) return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << "no recovery copy within 5 s";
    }

    // The real editor in a child process on scenePath, its first sphere's
    // radius set to `radius` and its recovery copy written, then killed with
    // SIGKILL.
    ::testing::AssertionResult killedEditorLeftACopy(const char* radius) const {
        QProcess child;
        child.setProcessChannelMode(QProcess::ForwardedErrorChannel);
        child.start(QStringLiteral(WHITTED_CRASH_CHILD_EXE),
                    {scenePath, QString::fromLatin1(radius)});
        if (!child.waitForStarted(10000))
            return ::testing::AssertionFailure() << "the child did not start";
        if (!child.waitForReadyRead(30000))
            return ::testing::AssertionFailure() << "the child never wrote its copy";
        if (child.readLine().trimmed() != QByteArray("ready"))
            return ::testing::AssertionFailure() << "the child did not say it was ready";
        child.kill();
        if (!child.waitForFinished(10000))
            return ::testing::AssertionFailure() << "the killed child did not end";
        if (child.exitStatus() != QProcess::CrashExit)
            return ::testing::AssertionFailure() << "the child was not killed";
        return ::testing::AssertionSuccess();
    }

    test::TempDir dir;
    QString recoveryDir, scenePath;
    Scene original;
};

TEST_F(AutosaveTest, BurstOfEdits_OneCopyOfTheLastScene_GoneWhenSaved) {
    MainWindow window;
    ASSERT_TRUE(window.openFile(scenePath));
    Autosave* autosave = window.autosave();
    autosave->setDelay(200);
    QSignalSpy written(autosave, &Autosave::written);
    for (int i = 1; i <= 5; ++i)
        window.document()->edit("edit", [i](Scene& s) { s.spheres[0].radius = 0.1 * i; });
    ASSERT_TRUE(written.wait(5000));
    QTest::qWait(400);
    EXPECT_EQ(written.count(), 1) << "one copy per burst";
    EXPECT_EQ(written.first().first().toString(), QString());
    const Scene copy = loadScene((autosave->slotPath() + ".json").toStdString());
    EXPECT_EQ(copy, window.document()->scene());
    EXPECT_EQ(copy.spheres[0].radius, 0.5);
    // The copy belongs to a running editor: nobody offers it.
    EXPECT_TRUE(Autosave::orphans(recoveryDir).empty());

    QString error;
    ASSERT_TRUE(window.document()->save(scenePath, &error)) << error.toStdString();
    EXPECT_FALSE(fs::exists((autosave->slotPath() + ".json").toStdString()));
}

TEST_F(AutosaveTest, UndoBackToTheFile_RemovesTheCopy) {
    MainWindow window;
    ASSERT_TRUE(window.openFile(scenePath));
    ASSERT_TRUE(editAndWaitForCopy(window));
    const std::string copy = (window.autosave()->slotPath() + ".json").toStdString();
    EXPECT_TRUE(fs::exists(copy));
    window.document()->undoStack()->undo();
    EXPECT_FALSE(fs::exists(copy));
}

TEST_F(AutosaveTest, NormalExit_LeavesNothingBehind) {
    {
        MainWindow window;
        ASSERT_TRUE(window.openFile(scenePath));
        ASSERT_TRUE(editAndWaitForCopy(window));
    }
    EXPECT_TRUE(recoveryFiles().empty()) << test::joined(recoveryFiles());
}

// The real editor in a child process, killed with SIGKILL after its copy is
// written; the next editor offers the copy, restores it on top of the file
// (unsaved; undo shows the file) and removes it.
TEST_F(AutosaveTest, KilledEditor_NextStartOffersAndRestoresTheEdits) {
    ASSERT_TRUE(killedEditorLeftACopy("0.777"));

    MainWindow window;
    window.show();
    ASSERT_EQ(window.offerRecovery(), 1);
    auto* box = window.findChild<QMessageBox*>("recoveryOffer");
    ASSERT_NE(box, nullptr);
    EXPECT_TRUE(box->text().contains("seed.json")) << box->text().toStdString();
    auto* restore = box->findChild<QPushButton*>("restoreButton");
    ASSERT_NE(restore, nullptr);
    restore->click();

    SceneDocument* doc = window.document();
    EXPECT_EQ(doc->scene().spheres[0].radius, 0.777);
    EXPECT_EQ(doc->filePath(), scenePath);
    EXPECT_TRUE(doc->isModified());
    doc->undoStack()->undo();
    EXPECT_EQ(doc->scene(), original);
    EXPECT_TRUE(Autosave::orphans(recoveryDir).empty());
    QTest::qWait(50);  // the next offer is queued: there is none
    EXPECT_EQ(window.findChild<QMessageBox*>("recoveryOffer"), nullptr);
}

// The copy is of seed.json, the editor was opened on another file: the offer
// says that restoring replaces that one, and Discard leaves it open.
TEST_F(AutosaveTest, CopyOfAnotherFile_OfferSaysItReplacesTheOneOpen) {
    ASSERT_TRUE(killedEditorLeftACopy("0.444"));

    const QString otherPath =
        QString::fromStdString(test::saveSceneIn(dir, original, "other.json"));
    MainWindow window;
    ASSERT_TRUE(window.openFile(otherPath));
    ASSERT_EQ(window.offerRecovery(), 1);
    auto* box = window.findChild<QMessageBox*>("recoveryOffer");
    ASSERT_NE(box, nullptr);
    EXPECT_TRUE(box->text().contains("changes to seed.json")) << box->text().toStdString();
    EXPECT_TRUE(box->text().contains("in place of other.json")) << box->text().toStdString();
    box->findChild<QPushButton*>("discardButton")->click();
    EXPECT_EQ(window.document()->filePath(), otherPath);
    EXPECT_FALSE(window.document()->isModified());
}

TEST_F(AutosaveTest, KilledEditor_DiscardKeepsTheSceneAndRemovesTheCopy) {
    ASSERT_TRUE(killedEditorLeftACopy("0.333"));

    MainWindow window;
    ASSERT_TRUE(window.openFile(scenePath));
    ASSERT_EQ(window.offerRecovery(), 1);
    auto* box = window.findChild<QMessageBox*>("recoveryOffer");
    ASSERT_NE(box, nullptr);
    // The copy is of the file open: nothing to say about replacing it.
    EXPECT_FALSE(box->text().contains("in place of")) << box->text().toStdString();
    box->findChild<QPushButton*>("discardButton")->click();
    EXPECT_EQ(window.document()->scene(), original);
    EXPECT_FALSE(window.document()->isModified());
    EXPECT_TRUE(Autosave::orphans(recoveryDir).empty());
}

}  // namespace
}  // namespace whitted::ui
