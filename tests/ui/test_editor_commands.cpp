// GUI tests of the editor's commands as a newcomer meets them: every shortcut
// the Keyboard and Mouse help lists, pressed in a shown window; Ctrl+Z from
// inside a field; Save As without ".json"; the export size locked to the
// scene's aspect; the Help menu, the About box, the tool bar and the tool tips.
#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QDialog>
#include <QFileDialog>
#include <QFileSystemModel>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QScrollBar>
#include <QSettings>
#include <QSlider>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTest>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QUndoStack>

#include <filesystem>
#include <functional>
#include <memory>

#include "editor/export_job.h"
#include "editor/help_dialogs.h"
#include "editor/main_window.h"
#include "image/image_io.h"
#include "panels/scene_panel.h"
#include "scene/free_spot.h"
#include "scene/scene_io.h"
#include "support/export_support.h"
#include "support/main_window_fixture.h"
#include "support/test_support.h"
#include "tracer/kernel_dispatch.h"
#include "tradeoff_dock/tradeoff_view.h"
#include "viewport/render_view.h"

namespace whitted::ui {
namespace {

namespace fs = std::filesystem;

// Closes every modal dialog as soon as it opens (Open, Save As, Export,
// questions), so that pressing their shortcuts cannot block the test.
class ModalCloser {
  public:
    ModalCloser() {
        timer_.setInterval(20);
        QObject::connect(&timer_, &QTimer::timeout, [this] {
            if (QWidget* modal = QApplication::activeModalWidget()) {
                ++closed;
                if (auto* dialog = qobject_cast<QDialog*>(modal))
                    dialog->reject();
                else
                    modal->close();
            }
        });
        timer_.start();
    }
    int closed = 0;

  private:
    QTimer timer_;
};

// Runs `act` on the first modal dialog of type D that opens within 30 s (a
// loaded CI machine is slow to build a file dialog). A dialog that `act` did not
// close within 10 s is rejected, so a test that fails to close it fails on its
// assertions instead of hanging in exec() until CTest's timeout.
template <class D>
void whenModalOpens(std::function<void(D*)> act) {
    auto* poll = new QTimer;
    auto tries = std::make_shared<int>(0);
    // Any shown modal D, not only the active modal widget: a dialog left from an
    // earlier test in the same process may still count as that.
    auto shownModal = []() -> D* {
        for (QWidget* w : QApplication::topLevelWidgets())
            if (auto* d = qobject_cast<D*>(w); d && d->isVisible() && d->isModal()) return d;
        return nullptr;
    };
    QObject::connect(poll, &QTimer::timeout, [poll, act, tries, shownModal] {
        if (auto* d = shownModal()) {
            poll->deleteLater();
            act(d);
            QTimer::singleShot(10000, d, [] {
                // Whatever is still open, a question the dialog asked included.
                for (QWidget* w : QApplication::topLevelWidgets()) {
                    auto* open = qobject_cast<QDialog*>(w);
                    if (!open || !open->isVisible()) continue;
                    auto* box = qobject_cast<QMessageBox*>(open);
                    ADD_FAILURE() << "still open 10 s after the test answered: "
                                  << open->windowTitle().toStdString()
                                  << (box ? " \"" + box->text().toStdString() + "\"" : "");
                    open->reject();
                }
            });
        } else if (++*tries > 1500) {
            poll->deleteLater();
        }
    });
    poll->start(20);
}

class EditorCommandsTest : public EditorWindowTest {
  protected:
    void SetUp() override {
        writeSeedFile();
        ASSERT_TRUE(showWindow({1200, 800}));
        QApplication::setActiveWindow(window.get());
        ASSERT_TRUE(QTest::qWaitForWindowActive(window.get()));
        ASSERT_TRUE(openFile(scenePath));
        view = window->renderView();
    }

    QAction* action(const QString& name) { return window->findChild<QAction*>(name); }

    RenderView* view = nullptr;
};

// The help's table is what the keys do. Every shortcut it
// lists is pressed, the editor lives on, and Home and F did their job.
TEST_F(EditorCommandsTest, EveryListedShortcut_PressedInShownWindow_EditorLivesOn) {
    const QList<ControlRow> rows = controlRows(window.get(), RenderView::mouseControls());
    ModalCloser closer;
    int pressed = 0;
    QList<QKeySequence> quit;
    for (const ControlRow& row : rows) {
        if (row.mouse) continue;
        for (const QString& keys : row.keys.split(QStringLiteral(", "))) {
            const QKeySequence seq = QKeySequence::fromString(keys, QKeySequence::NativeText);
            ASSERT_FALSE(seq.isEmpty()) << keys.toStdString();
            if (seq == QKeySequence(QStringLiteral("Ctrl+Q"))) {
                quit << seq;
                continue;
            }
            // A sphere selected and the view focused: F and the camera keys have work to do.
            window->scenePanel()->select(ItemKind::Sphere, 0);
            view->setFocus();
            QTest::keySequence(view, seq);
            QTest::qWait(5);
            ++pressed;
            ASSERT_TRUE(window->isVisible()) << "after " << keys.toStdString();
        }
    }
    EXPECT_GE(pressed, 25);
    EXPECT_GT(closer.closed, 0) << "Open, Save As and Export open their dialogs";

    // Home returns to the opened camera; F looks at the selected sphere.
    window->openFile(scenePath);
    const Camera home = doc->scene().camera;
    QApplication::setActiveWindow(window.get());
    view->setFocus();

    QTest::keyClick(view, Qt::Key_Left);
    ASSERT_FALSE(doc->scene().camera == home) << "Left orbits";
    QTest::keyClick(view, Qt::Key_Home);
    EXPECT_TRUE(doc->scene().camera == home);
    window->scenePanel()->select(ItemKind::Sphere, 1);
    QTest::keyClick(view, Qt::Key_F);
    EXPECT_TRUE(doc->scene().camera.lookAt == doc->scene().spheres[1].center);
    // The menu items do the same, without a key.
    action(QStringLiteral("resetCamera"))->trigger();
    EXPECT_TRUE(doc->scene().camera == home);

    window->openFile(scenePath);  // unmodified: Quit asks nothing
    ASSERT_EQ(quit.size(), 1);
    QTest::keySequence(view, quit.front());
    EXPECT_FALSE(window->isVisible()) << "Ctrl+Q closes the unmodified window";
}

// Scene undo works while the focus is still in the field just edited.
TEST_F(EditorCommandsTest, CtrlZ_WithFocusInEditedField_UndoesTheSceneEdit) {
    window->scenePanel()->select(ItemKind::Sphere, 0);
    auto* radius = window->findChild<QDoubleSpinBox*>(QStringLiteral("sphereRadius"));
    ASSERT_NE(radius, nullptr);
    const double before = doc->scene().spheres[0].radius;
    radius->setFocus();
    radius->selectAll();
    QTest::keyClicks(radius, QStringLiteral("1.25"));
    QTest::keyClick(radius, Qt::Key_Return);
    ASSERT_DOUBLE_EQ(doc->scene().spheres[0].radius, 1.25);
    ASSERT_TRUE(radius->hasFocus());
    while (doc->scene().spheres[0].radius != before && doc->undoStack()->canUndo())
        QTest::keySequence(radius, QKeySequence::Undo);
    EXPECT_DOUBLE_EQ(doc->scene().spheres[0].radius, before);
    EXPECT_DOUBLE_EQ(radius->value(), before) << "the field shows the undone value";
    EXPECT_FALSE(window->isWindowModified());
    QTest::keySequence(radius, QKeySequence(QStringLiteral("Ctrl+Shift+Z")));
    EXPECT_NE(doc->scene().spheres[0].radius, before) << "Ctrl+Shift+Z redoes";
}

// Shift+A adds to the list shown, as in Blender; typed into a text field it
// stays a capital A and adds nothing.
TEST_F(EditorCommandsTest, ShiftA_AddsToTheListShown_InTheFilterItIsTyped) {
    // A ball where the camera looks, as in glass.json: Add goes beside it.
    ASSERT_TRUE(doc->edit(QStringLiteral("move"), [](Scene& s) {
        s.spheres[0].center = s.camera.lookAt;
        s.spheres[0].radius = 0.5;
    }));
    const Scene before = doc->scene();
    const std::size_t spheres = before.spheres.size();
    view->setFocus();
    QTest::keyClick(view, Qt::Key_A, Qt::ShiftModifier);
    ASSERT_EQ(doc->scene().spheres.size(), spheres + 1);
    // Where no sphere is already: at the look-at point or beside it.
    const Sphere& added = doc->scene().spheres.back();
    EXPECT_EQ(added.center, freeSpotForSphere(before, added.radius));
    EXPECT_NE(added.center, before.camera.lookAt);
    EXPECT_EQ(action(QStringLiteral("addAction"))->shortcut(),
              QKeySequence(QStringLiteral("Shift+A")));

    auto* filter = window->findChild<QLineEdit*>(QStringLiteral("sphereListFilter"));
    ASSERT_NE(filter, nullptr);
    filter->setFocus();
    QTest::keyClick(filter, 'A', Qt::ShiftModifier);
    EXPECT_EQ(filter->text(), QStringLiteral("A"));
    EXPECT_EQ(doc->scene().spheres.size(), spheres + 1);
}

// A name typed without ".json" is saved as name.json.
TEST_F(EditorCommandsTest, SaveAs_NameWithoutExtension_WritesDotJson) {
    const QString typed = QString::fromStdString((dir.path() / "my scene").string());
    const QString folder = QString::fromStdString(dir.path().string());
    whenModalOpens<QFileDialog>([typed, folder](QFileDialog* d) {
        // The dialog lists the folder in the background and, once listed,
        // selects the scene's own file (seed.json) in its name field, which
        // selectFile() leaves alone once the field has the focus (seen: the
        // overwrite question for seed.json). So: wait for the listing, then
        // type into the field as a person does.
        auto* files = d->findChild<QFileSystemModel*>();
        auto* name = d->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"));
        ASSERT_TRUE(files && name);
        EXPECT_TRUE(
            QTest::qWaitFor([&] { return files->rowCount(files->index(folder)) > 0; }, 10000));
        QTest::qWait(50);
        name->setText(typed);
        // Then Save (accept() is protected).
        QMetaObject::invokeMethod(d, "accept", Qt::QueuedConnection);
    });
    action(QStringLiteral("Save As"))->trigger();
    EXPECT_TRUE(fs::exists(dir.path() / "my scene.json"));
    EXPECT_FALSE(fs::exists(dir.path() / "my scene"));
    EXPECT_EQ(doc->filePath(), typed + QStringLiteral(".json"));
    EXPECT_EQ(loadScene((dir.path() / "my scene.json").string()), doc->scene());
}

// The export size keeps the scene's aspect unless unlocked, and says so.
TEST_F(EditorCommandsTest, ExportSize_LockedToSceneAspect_UnlockedSaysFramingDiffers) {
    Scene scene = doc->scene();
    scene.render.width = 640;
    scene.render.height = 480;
    ExportDialog dialog(scene, std::nullopt, QString::fromStdString(dir.path().string()), "out");
    dialog.show();
    auto* width = dialog.findChild<QSpinBox*>(QStringLiteral("exportWidth"));
    auto* height = dialog.findChild<QSpinBox*>(QStringLiteral("exportHeight"));
    auto* lock = dialog.findChild<QAbstractButton*>(QStringLiteral("exportAspectLock"));
    auto* note = dialog.findChild<QLabel*>(QStringLiteral("exportAspectNote"));
    ASSERT_TRUE(width && height && lock && note);
    EXPECT_TRUE(lock->isChecked());
    width->setValue(1920);
    EXPECT_EQ(height->value(), 1440);
    EXPECT_FALSE(note->isVisible());
    height->setValue(300);
    EXPECT_EQ(width->value(), 400);

    lock->click();
    width->setValue(1920);
    height->setValue(1080);
    EXPECT_TRUE(note->isVisible());
    EXPECT_TRUE(note->text().contains(QStringLiteral("framed differently")));
    EXPECT_EQ(dialog.settings().render.width, 1920);
    EXPECT_EQ(dialog.settings().render.height, 1080);

    // A common size of another aspect unlocks rather than bends it.
    lock->click();
    ASSERT_TRUE(lock->isChecked());
    auto* common = dialog.findChild<QComboBox*>(QStringLiteral("exportCommonSize"));
    const int fullHd = common->findText(QStringLiteral("Full HD"), Qt::MatchStartsWith);
    ASSERT_GT(fullHd, 0);
    common->setCurrentIndex(fullHd);
    emit common->activated(fullHd);
    EXPECT_EQ(width->value(), 1920);
    EXPECT_EQ(height->value(), 1080);
    EXPECT_FALSE(lock->isChecked());
    EXPECT_TRUE(note->isVisible());
}

// The export dialog offers a turntable; its frames are
// numbered files, frame 1 the still the same dialog exports without one.
TEST_F(EditorCommandsTest, ExportTurntable_WritesNumberedFramesTheFirstOfThemTheStill) {
    Scene scene = doc->scene();
    scene.render.width = 32;
    scene.render.height = 24;
    ExportDialog dialog(scene, std::nullopt, QString::fromStdString(dir.path().string()), "spin");
    auto* frames = dialog.findChild<QSpinBox*>(QStringLiteral("exportTurntable"));
    ASSERT_NE(frames, nullptr);
    EXPECT_EQ(dialog.settings().turntableFrames, 0) << "a still unless asked";
    frames->setValue(3);
    const auto exportWith = [&](const ExportSettings& settings) {
        const ExportOutcome exported = exportAndWait(scene, settings);
        EXPECT_TRUE(exported.finished && exported.ok) << exported.message.toStdString();
        return exported.message;
    };
    const QString message = exportWith(dialog.settings());
    EXPECT_TRUE(message.contains(QStringLiteral("3 frames"))) << message.toStdString();
    ExportSettings still = dialog.settings();
    still.turntableFrames = 0;
    still.path = QString::fromStdString((dir.path() / "still.png").string());
    exportWith(still);
    EXPECT_EQ(test::joined(dir.entries()),
              "[seed.json, spin.0001.png, spin.0002.png, spin.0003.png, still.png]");
    EXPECT_EQ(readImage(dir.path() / "spin.0001.png"), readImage(dir.path() / "still.png"));
    EXPECT_NE(readImage(dir.path() / "spin.0002.png"), readImage(dir.path() / "still.png"));
}

// The Render tab picks a common size, one undo step, and the view frames it.
TEST_F(EditorCommandsTest, RenderTabCommonSize_SetsSizeInOneStep_ViewTakesItsAspect) {
    auto* common = window->findChild<QComboBox*>(QStringLiteral("renderCommonSize"));
    ASSERT_NE(common, nullptr);
    const int hd = common->findText(QStringLiteral("HD 720p"), Qt::MatchStartsWith);
    ASSERT_GT(hd, 0);
    const int steps = doc->undoStack()->count();
    emit common->activated(hd);
    EXPECT_EQ(doc->scene().render.width, 1280);
    EXPECT_EQ(doc->scene().render.height, 720);
    EXPECT_EQ(doc->undoStack()->count(), steps + 1);
    const QRect r = view->imageRect();
    EXPECT_NEAR(double(r.width()) / r.height(), 16.0 / 9.0, 0.02);
    doc->undoStack()->undo();
    EXPECT_EQ(doc->scene().render.width, kWidth);
}

// The Render menu ticks the preset the settings match, and none when custom.
TEST_F(EditorCommandsTest, PresetShortcut_TicksThatPreset_CustomTicksNone) {
    QTest::keySequence(window.get(), QKeySequence(QStringLiteral("Ctrl+2")));
    EXPECT_TRUE(action(QStringLiteral("presetPreview"))->isChecked());
    EXPECT_FALSE(action(QStringLiteral("presetDraft"))->isChecked());
    doc->edit("samples", [](Scene& s) { s.render.samplesPerPixel = 3; });
    for (const char* name : {"presetDraft", "presetPreview", "presetFinal"})
        EXPECT_FALSE(action(QString::fromLatin1(name))->isChecked()) << name;
    doc->undoStack()->undo();
    EXPECT_TRUE(action(QStringLiteral("presetPreview"))->isChecked());
}

// F1 opens the table of every control, the camera keys and the mouse among them.
TEST_F(EditorCommandsTest, KeyboardHelp_ListsEveryShortcutAndTheMouse) {
    QTest::keySequence(window.get(), QKeySequence::HelpContents);
    auto* dialog = window->findChild<QDialog*>(QStringLiteral("keyboardHelp"));
    ASSERT_NE(dialog, nullptr);
    auto* table = dialog->findChild<QTableWidget*>(QStringLiteral("controlsTable"));
    ASSERT_NE(table, nullptr);
    // One line per key: "Ctrl+Z = Undo".
    QStringList lines;
    for (int r = 0; r < table->rowCount(); ++r)
        for (const QString& key : table->item(r, 1)->text().split(", "))
            lines << key + " = " + table->item(r, 2)->text();
    for (const QString& expected :
         {QStringLiteral("Home = Reset Camera"), QStringLiteral("F = Frame Selected Sphere"),
          QStringLiteral("Left = Orbit Left"), QStringLiteral("W = Fly Forward"),
          QStringLiteral("G = Move Selected"), QStringLiteral("S = Scale Selected Spheres"),
          QStringLiteral("B = Box Select"), QStringLiteral("A = All"),
          QStringLiteral("Alt+A = None"), QStringLiteral("Ctrl+I = Invert"),
          QStringLiteral("Shift+L = Same Material"), QStringLiteral("Shift+D = Duplicate and Move"),
          QStringLiteral("Ctrl+C = Copy"), QStringLiteral("Ctrl+V = Paste"),
          QStringLiteral("Shift+` = Fly Mode"), QStringLiteral("Ctrl+Z = Undo"),
          QStringLiteral("Ctrl+S = Save"),
          QStringLiteral("Left drag = Orbit the camera about the point where the drag starts")})
        EXPECT_TRUE(lines.contains(expected)) << expected.toStdString();
    // Every action with a shortcut is listed with it.
    for (const QAction* a : window->findChildren<QAction*>())
        for (const QKeySequence& k : a->shortcuts()) {
            bool found = false;
            for (int r = 0; r < table->rowCount() && !found; ++r)
                found = table->item(r, 1)->text().split(", ").contains(
                    k.toString(QKeySequence::NativeText));
            EXPECT_TRUE(found) << k.toString().toStdString() << " of " << a->text().toStdString();
        }
    // Wide enough that no row's text hides behind a horizontal scroll bar
    // (at 620 pixels the mouse's rows did).
    ASSERT_TRUE(QTest::qWaitForWindowExposed(dialog));
    EXPECT_LE(table->horizontalHeader()->length(), table->viewport()->width());
    EXPECT_FALSE(table->horizontalScrollBar()->isVisible());
    dialog->close();
}

TEST_F(EditorCommandsTest, About_NamesVersionQtAndOpenImageIO) {
    action(QStringLiteral("aboutAction"))->trigger();
    auto* box = window->findChild<QMessageBox*>(QStringLiteral("aboutBox"));
    ASSERT_NE(box, nullptr);
    const QString text = box->text() + box->informativeText();
    EXPECT_TRUE(text.contains(QStringLiteral("0.1.0"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("Qt ") + qVersion())) << text.toStdString();
    EXPECT_TRUE(text.contains(QString::fromStdString("OpenImageIO " + openImageIOVersion())));
    EXPECT_NE(openImageIOVersion().substr(0, 2), "0.");
    EXPECT_TRUE(text.contains(QString::fromStdString(activeKernelDescription())));
    box->close();
}

// A tool bar with the common commands, icons, and keys in every tool tip.
TEST_F(EditorCommandsTest, ToolBar_HasTheCommonCommandsWithIconsAndShortcutTips) {
    auto* bar = window->findChild<QToolBar*>(QStringLiteral("mainToolBar"));
    ASSERT_NE(bar, nullptr);
    EXPECT_TRUE(bar->isVisible());
    QStringList names;
    for (QAction* a : bar->actions()) {
        if (a->isSeparator()) continue;
        QWidget* w = bar->widgetForAction(a);
        auto* button = qobject_cast<QToolButton*>(w);
        ASSERT_NE(button, nullptr);
        // A pixmap, not only a name: the theme's or our own from resources/.
        EXPECT_FALSE(button->icon().pixmap(24).isNull()) << button->text().toStdString();
        names << (a->objectName().isEmpty() ? w->objectName() : a->objectName());
    }
    EXPECT_EQ(names.mid(0, 6),
              QStringList({"Open", "Save", "undo", "redo", "Export Image", "presetButton"}));
    EXPECT_EQ(names.size(), 7);
    EXPECT_EQ(bar->actions().last(), window->tradeoffView()->pinAction());
    for (const QAction* a : window->findChildren<QAction*>()) {
        if (!a->shortcuts().isEmpty()) {
            EXPECT_TRUE(a->toolTip().contains(a->shortcut().toString(QKeySequence::NativeText)))
                << a->toolTip().toStdString();
        }
    }
}

// Hovering any field of the panels says what it edits.
TEST_F(EditorCommandsTest, EveryFieldOfThePanels_HasAToolTip) {
    int fields = 0;
    for (QWidget* w : window->findChildren<QWidget*>()) {
        const bool input = qobject_cast<QAbstractSpinBox*>(w) || qobject_cast<QComboBox*>(w) ||
                           qobject_cast<QSlider*>(w);
        if (!input || qobject_cast<QAbstractSpinBox*>(w->parentWidget())) continue;
        if (w->window() != window.get()) continue;
        ++fields;
        EXPECT_FALSE(w->toolTip().isEmpty()) << w->objectName().toStdString();
    }
    EXPECT_GT(fields, 20);
    auto* radius = window->findChild<QDoubleSpinBox*>(QStringLiteral("sphereRadius"));
    EXPECT_EQ(radius->toolTip(), QStringLiteral("Radius"));
    auto* x = window->findChild<QDoubleSpinBox*>(QStringLiteral("sphereCenterX"));
    ASSERT_NE(x, nullptr);
    EXPECT_EQ(x->toolTip(), QStringLiteral("Centre: x"));
}

}  // namespace
}  // namespace whitted::ui
