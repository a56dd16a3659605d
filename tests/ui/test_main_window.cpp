// GUI tests of the editor: the real MainWindow (document, render worker, view,
// panels) driven offscreen through its widgets, mouse and keys, checking what the
// user sees: the pixels of the view, the selection, the title, the files written.
//
// Scenes are rendered at 160x120 to keep every test well under a second of
// rendering. Images are compared exactly (tolerance 0): the contract promises
// bit-identical renders (SPEC §4); on a mismatch the two images and a diff are
// written to the temporary directory and the paths printed.
#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>
#include <QUndoStack>
#include <QWindow>

#include <glm/geometric.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "camera/camera_control.h"
#include "editor/export_job.h"
#include "editor/main_window.h"
#include "image/image_io.h"
#include "panels/color_button.h"
#include "panels/number_field.h"
#include "panels/scene_panel.h"
#include "scene/scene_io.h"
#include "support/main_window_fixture.h"
#include "support/test_support.h"
#include "tracer/renderer.h"
#include "viewport/image_convert.h"
#include "viewport/render_view.h"

namespace whitted::ui {
namespace {

// 1.
TEST_F(MainWindowTest, MaterialDiffuse_EditedToRed_BallTurnsRedAndBackgroundStays) {
    const QImage before = view->frame();
    const QPoint centre = pixelOf(doc->scene(), doc->scene().spheres[kBlueBall].center);
    ASSERT_TRUE(blueDominant(before.pixelColor(centre)))
        << before.pixelColor(centre).name().toStdString();

    window->scenePanel()->select(ItemKind::Material, 0);  // "blue"
    auto* diffuse = window->findChild<ColorButton*>("materialDiffuse");
    ASSERT_NE(diffuse, nullptr);
    ASSERT_TRUE(diffuse->isVisibleTo(window.get())) << "the material's diffuse button is not shown";
    EXPECT_EQ(diffuse->color(), Vec3(0, 0, 1));

    const int n = log->completed;
    diffuse->edit(Vec3(1, 0, 0));
    ASSERT_TRUE(waitForRender(n));
    EXPECT_EQ(doc->scene().materials[0].diffuse, Vec3(1, 0, 0));
    EXPECT_EQ(doc->undoStack()->count(), 1);

    const QImage after = view->frame();
    EXPECT_TRUE(redDominant(after.pixelColor(centre)))
        << after.pixelColor(centre).name().toStdString();
    // Pixels whose camera ray meets no sphere show the background, which no colour changes.
    int background = 0, changed = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            changed += before.pixel(x, y) != after.pixel(x, y);
            if (pickSphere(doc->scene(), x + 0.5, y + 0.5)) continue;
            ++background;
            ASSERT_EQ(before.pixel(x, y), after.pixel(x, y))
                << "background pixel " << x << ", " << y;
        }
    EXPECT_GT(background, 100);
    // The ball (~15 px radius) and its reflections change; most of the image does not.
    EXPECT_GT(changed, 400);
    EXPECT_LT(changed, kWidth * kHeight / 4);
}

// 2: the camera by keys and mouse is in test_view_camera.cpp.

// 3.
// An edit shows its coarse preview first: one colour per 8x8 block of the
// render, each the colour of the camera ray through the block's middle pixel,
// placed where those pixels are in the view.
TEST_F(MainWindowTest, Preview_ShowsEachBlockWhereItsPixelsAre) {
    QImage preview, seen;
    int block = 0;
    const QMetaObject::Connection c =
        QObject::connect(window.get(), &MainWindow::frameShown, [&](const RenderFrame& f) {
            if (!f.preview || !preview.isNull()) return;
            preview = f.image;
            block = f.block;
            seen = view->grab().toImage().convertToFormat(QImage::Format_RGB32);
        });
    const int n = log->completed;
    ASSERT_TRUE(doc->edit("radius", [](Scene& s) {
        s.spheres[kBlueBall].radius *= 1.1;
        s.render.samplesPerPixel = 1;  // each full-size pixel one camera ray, as each block's
    }));
    ASSERT_TRUE(waitForRender(n));
    QObject::disconnect(c);
    ASSERT_FALSE(preview.isNull()) << "no preview frame was shown";
    EXPECT_EQ(block, 8);
    EXPECT_EQ(preview.size(), QSize(kWidth / 8, kHeight / 8));
    const QImage full = view->frame();
    ASSERT_EQ(full.size(), QSize(kWidth, kHeight));
    // Where the full render shows through, the overlay (lights, selection)
    // is not drawn over it: only there is the preview compared.
    const QImage seenFull = view->grab().toImage().convertToFormat(QImage::Format_RGB32);
    const QRect r = view->imageRect();
    const auto widgetPoint = [&](double x, double y) {
        return QPoint(r.x() + int(x * r.width() / kWidth), r.y() + int(y * r.height() / kHeight));
    };
    int compared = 0, differentFromFull = 0;
    for (int by = 0; by < preview.height(); ++by)
        for (int bx = 0; bx < preview.width(); ++bx) {
            const int x = 8 * bx + 4, y = 8 * by + 4;  // the block's middle pixel
            EXPECT_EQ(preview.pixel(bx, by), full.pixel(x, y)) << "block " << bx << ", " << by;
            // The middle pixel and one inside the block beside it.
            for (const int px : {x, x - 3}) {
                const QPoint at = widgetPoint(px + 0.5, y + 0.5);
                if (seenFull.pixel(at) != full.pixel(px, y)) continue;  // under the overlay
                ++compared;
                differentFromFull += seen.pixel(at) != full.pixel(px, y);
                EXPECT_EQ(seen.pixel(at), preview.pixel(bx, by))
                    << "block " << bx << ", " << by << ", pixel " << px;
            }
        }
    EXPECT_GT(compared, 2 * preview.width() * preview.height() * 9 / 10);
    EXPECT_GT(differentFromFull, 0) << "the preview looks like the full render: not blocky";
}

// A preview that takes longer than its budget makes the next one's blocks
// twice as large, down to 32 across the picture or a tile; one that would fit
// four times over makes them finer again, never finer than 8. A block kept
// from a wider scene is made finer for a narrower one.
TEST(PreviewBlock, CoarserWhileSlow_FinerOnceTheFinerFits) {
    EXPECT_EQ(nextPreviewBlock(8, 1.0, 640), 8);
    EXPECT_EQ(nextPreviewBlock(8, kPreviewBudgetMs + 0.1, 640), 16);
    EXPECT_EQ(nextPreviewBlock(16, kPreviewBudgetMs + 0.1, 640), 16) << "640 / 32 is 20 across";
    EXPECT_EQ(nextPreviewBlock(16, kPreviewBudgetMs + 0.1, 1280), 32);
    EXPECT_EQ(nextPreviewBlock(32, kPreviewBudgetMs + 0.1, 4096), 32) << "a tile";
    EXPECT_EQ(nextPreviewBlock(8, 100.0, 160), 8) << "160 / 16 is 10 across";
    EXPECT_EQ(nextPreviewBlock(16, kPreviewBudgetMs / 2, 640), 16) << "at 8, 4 times that";
    EXPECT_EQ(nextPreviewBlock(16, kPreviewBudgetMs / 8, 640), 8);
    EXPECT_EQ(nextPreviewBlock(8, 0.0, 640), 8);
    // A block kept from a wider picture, for a narrower one.
    EXPECT_EQ(previewBlockFor(16, 160), 8);
    EXPECT_EQ(previewBlockFor(32, 640), 16);
    EXPECT_EQ(previewBlockFor(32, 1280), 32);
    EXPECT_EQ(previewBlockFor(8, 100), 8);
}

TEST_F(MainWindowTest, Click_OnSpherePixel_SelectsThatSphere) {
    ScenePanel* panel = window->scenePanel();
    const Scene& s = doc->scene();
    const int undoCount = doc->undoStack()->count();

    QTest::mouseClick(view, Qt::LeftButton, {},
                      widgetPoint(project(s, s.spheres[kPurpleBall].center)));
    EXPECT_EQ(panel->currentKind(), ItemKind::Sphere);
    EXPECT_EQ(panel->currentIndex(), int(kPurpleBall));

    QTest::mouseClick(view, Qt::LeftButton, {},
                      widgetPoint(project(s, s.spheres[kBlueBall].center)));
    EXPECT_EQ(panel->currentKind(), ItemKind::Sphere);
    EXPECT_EQ(panel->currentIndex(), int(kBlueBall));

    // The floor, at the bottom middle of the image.
    QTest::mouseClick(view, Qt::LeftButton, {}, widgetPoint({kWidth / 2.0, kHeight - 2.0}));
    EXPECT_EQ(panel->currentIndex(), int(kFloor));

    // Clicks pick; they are not edits.
    EXPECT_EQ(doc->undoStack()->count(), undoCount);
    EXPECT_EQ(doc->scene().camera, loadScene(scenePath.toStdString()).camera);
}

// 4.
TEST_F(MainWindowTest, Undo_AfterRadiusEdit_RestoresImageBitForBit) {
    const QImage original = view->frame();
    ASSERT_TRUE(editAndWait([](Scene& s) { s.spheres[kBlueBall].radius = 0.8; }));
    const QImage edited = view->frame();
    EXPECT_FALSE(identical(edited, original));

    ASSERT_TRUE(undoAndWait());
    EXPECT_EQ(doc->scene().spheres[kBlueBall].radius, 0.6);
    EXPECT_TRUE(sameImage(view->frame(), original));

    ASSERT_TRUE(undoAndWait(/*redo=*/true));
    EXPECT_TRUE(sameImage(view->frame(), edited));
}

// 5.
TEST_F(MainWindowTest, SaveThenOpen_InFreshWindow_RoundTripsSceneAndBytes) {
    ASSERT_TRUE(editAndWait([](Scene& s) {
        s.lights[0].intensity = 0.75;
        s.spheres[kWhiteBall].center.x = -0.3;
    }));
    const QString saved = QString::fromStdString((dir / "saved.json").string());
    QString error;
    ASSERT_TRUE(doc->save(saved, &error)) << error.toStdString();
    EXPECT_FALSE(doc->isModified());
    EXPECT_EQ(doc->filePath(), saved);
    EXPECT_EQ(test::readFile(saved.toStdString()), sceneToJson(doc->scene()));

    MainWindow other;
    ASSERT_TRUE(other.openFile(saved)) << other.lastError().toStdString();
    EXPECT_EQ(other.document()->scene(), doc->scene());
    EXPECT_FALSE(other.document()->isModified());

    const QString again = QString::fromStdString((dir / "again.json").string());
    ASSERT_TRUE(other.document()->save(again, &error)) << error.toStdString();
    EXPECT_EQ(test::readFile(again.toStdString()), test::readFile(saved.toStdString()));
}

// 6.
TEST_F(MainWindowTest, Export_PngAndExr_WritesTheCoreRenderOfTheSettings) {
    for (const char* name : {"export.exr", "export.png"}) {
        SCOPED_TRACE(name);
        ExportSettings settings;
        settings.path = QString::fromStdString((dir / name).string());
        settings.render = doc->scene().render;
        settings.render.width = 96;  // none of them the scene's own
        settings.render.height = 64;
        settings.render.samplesPerPixel = 4;
        settings.render.maxDepth = 3;

        QSignalSpy finished(window.get(), &MainWindow::exportFinished);
        window->startExport(settings);
        ASSERT_TRUE(finished.wait(kRenderTimeoutMs));
        ASSERT_EQ(finished.count(), 1);
        ASSERT_TRUE(finished[0][0].toBool()) << finished[0][1].toString().toStdString();

        Scene expectedScene = doc->scene();
        expectedScene.render = settings.render;
        const RenderResult expected = render(expectedScene);
        ASSERT_TRUE(expected.completed);

        const Image read = readImage((dir / name).string());
        EXPECT_EQ(read.width, 96);
        EXPECT_EQ(read.height, 64);
        if (std::string(name).ends_with(".exr")) {
            EXPECT_TRUE(read == expected.image) << "the EXR's floats differ from the core render";
        } else {
            EXPECT_TRUE(sameImage(QImage(settings.path), toQImage(expected.image)));
        }
    }
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"export.exr", "export.png", "seed.json"}));
    // Exporting is not an edit.
    EXPECT_FALSE(doc->isModified());
}

// 7.
TEST_F(MainWindowTest, OpenBrokenFile_KeepsSceneTitleAndNamesTheProblem) {
    ASSERT_TRUE(editAndWait([](Scene& s) { s.spheres[kBlueBall].radius = 0.7; }));
    const Scene before = doc->scene();
    const QString title = shownTitle();
    const QImage image = view->frame();

    std::string text = test::readFile(test::kSeedScenePath);
    const std::string radius = "\"radius\": 0.6";
    const auto at = text.find(radius);  // the first sphere's
    ASSERT_NE(at, std::string::npos);
    text.replace(at, radius.size(), "\"radius\": -1");
    const QString broken = QString::fromStdString((dir / "broken.json").string());
    test::writeFile(broken.toStdString(), text);

    EXPECT_FALSE(window->openFile(broken));
    EXPECT_EQ(doc->scene(), before);
    EXPECT_EQ(doc->filePath(), scenePath);
    EXPECT_TRUE(doc->isModified());
    EXPECT_EQ(doc->undoStack()->count(), 1);  // the history survives too
    EXPECT_EQ(shownTitle(), title);
    EXPECT_TRUE(window->lastError().contains("broken.json")) << window->lastError().toStdString();
    EXPECT_TRUE(window->lastError().contains("spheres[0].radius"))
        << window->lastError().toStdString();
    QTest::qWait(100);  // nothing is re-rendered
    EXPECT_TRUE(sameImage(view->frame(), image));
}

// 8.
TEST_F(MainWindowTest, Title_ShowsFileNameAndStarOnlyWhileModified) {
    EXPECT_EQ(shownTitle(), QStringLiteral("seed.json — Whitted"));
    EXPECT_FALSE(window->isWindowModified());

    ASSERT_TRUE(editAndWait([](Scene& s) { s.lights[0].intensity = 0.5; }));
    EXPECT_TRUE(window->isWindowModified());
    EXPECT_EQ(shownTitle(), QStringLiteral("seed.json* — Whitted"));

    ASSERT_TRUE(undoAndWait());
    EXPECT_FALSE(window->isWindowModified());
    EXPECT_EQ(shownTitle(), QStringLiteral("seed.json — Whitted"));

    ASSERT_TRUE(undoAndWait(/*redo=*/true));
    EXPECT_EQ(shownTitle(), QStringLiteral("seed.json* — Whitted"));
    QString error;
    const QString renamed = QString::fromStdString((dir / "renamed.json").string());
    ASSERT_TRUE(doc->save(renamed, &error)) << error.toStdString();
    EXPECT_EQ(shownTitle(), QStringLiteral("renamed.json — Whitted"));
}

// 9.
TEST_F(MainWindowTest, RapidEdits_FinalViewIsTheNewestSceneNotAStaleFrame) {
    const int n = log->completed;
    const size_t shownBefore = log->generations.size();
    // A first edit whose frames, the complete one included, wait in the GUI
    // thread's queue while it is busy: they are stale once the next edit is made.
    ASSERT_TRUE(doc->edit("radius", [](Scene& s) { s.spheres[kBlueBall].radius = 0.25; }));
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    for (int i = 0; i < 20; ++i)  // no event processing in between: 20 requests in a row
        ASSERT_TRUE(
            doc->edit("radius", [i](Scene& s) { s.spheres[kBlueBall].radius = 0.3 + 0.03 * i; }));
    ASSERT_TRUE(waitForRender(n));
    const QImage expected = coreRender(doc->scene());
    EXPECT_TRUE(sameImage(view->frame(), expected));
    // Nothing older arrives later and overwrites it.
    QTest::qWait(300);
    EXPECT_EQ(log->completed, n + 1);
    EXPECT_TRUE(sameImage(view->frame(), expected));
    // Every frame the view showed since the edits belongs to the last request.
    ASSERT_GT(log->generations.size(), shownBefore);
    for (size_t i = shownBefore; i < log->generations.size(); ++i)
        EXPECT_EQ(log->generations[i], log->generations.back()) << "frame " << i - shownBefore;
}

// Every extreme scene shows its numbers exactly as the file has them: a floor
// centre of -1e9 - 0.5 or a radius of 5e-5 is neither clamped nor rounded, so
// the next edit cannot write a changed value back.
TEST_F(MainWindowTest, ExtremeScenes_FieldsShowEveryCentreAndRadiusExactly) {
    int checked = 0;
    for (const auto& entry : std::filesystem::directory_iterator(WHITTED_SCENES_DIR "/extremes")) {
        if (entry.path().extension() != ".json") continue;
        SCOPED_TRACE(entry.path().filename().string());
        const Scene scene = loadScene(entry.path());
        ASSERT_TRUE(window->openFile(QString::fromStdString(entry.path().string())))
            << window->lastError().toStdString();
        for (int i = 0; i < int(scene.spheres.size()); ++i) {
            window->scenePanel()->select(ItemKind::Sphere, i);
            const Sphere& sp = scene.spheres[i];
            const char* axes[] = {"sphereCenterX", "sphereCenterY", "sphereCenterZ"};
            for (int a = 0; a < 3; ++a) {
                auto* spin = window->findChild<NumberSpinBox*>(axes[a]);
                ASSERT_NE(spin, nullptr);
                EXPECT_EQ(spin->value(), sp.center[a]) << sp.name << " " << axes[a];
            }
            auto* radius = window->findChild<NumberSpinBox*>("sphereRadius");
            ASSERT_NE(radius, nullptr);
            EXPECT_EQ(radius->value(), sp.radius) << sp.name;
            ++checked;
        }
        EXPECT_FALSE(doc->isModified()) << "showing the scene changed it";
    }
    EXPECT_GT(checked, 20);
}

// Stepping does not show binary noise: 0.2 stepped by 0.1 is 0.3, not
// 0.30000000000000004, and the edit stores 0.3.
TEST_F(MainWindowTest, RadiusStepUp_FromPointTwo_GivesExactlyPointThree) {
    ASSERT_TRUE(editAndWait([](Scene& s) { s.spheres[0].radius = 0.2; }));
    window->scenePanel()->select(ItemKind::Sphere, 0);
    auto* radius = window->findChild<NumberSpinBox*>("sphereRadius");
    ASSERT_NE(radius, nullptr);
    radius->setStepType(QAbstractSpinBox::DefaultStepType);
    radius->setSingleStep(0.1);
    radius->stepBy(1);
    EXPECT_EQ(doc->scene().spheres[0].radius, 0.3);
    EXPECT_EQ(radius->text(), QStringLiteral("0.3"));
}

// Export errors: a missing directory, a full disk and an unknown
// extension each end the export with a message naming the file; no file is
// left, the scene is untouched and unmodified.
TEST_F(MainWindowTest, ExportErrors_MessageNamesTheFileAndNothingIsLeftOrChanged) {
    const Scene before = doc->scene();
    fs::create_symlink("/dev/full", dir / "full.png");
    const std::vector<std::pair<std::string, std::string>> cases = {
        {(dir / "missing" / "out.png").string(), "out.png"},
        {(dir / "full.png").string(), "No space left on device"},
        {(dir / "out.bmp").string(), "unknown image extension"},
    };
    for (const auto& [path, expected] : cases) {
        SCOPED_TRACE(path);
        ExportSettings settings;
        settings.path = QString::fromStdString(path);
        settings.render = doc->scene().render;
        QSignalSpy finished(window.get(), &MainWindow::exportFinished);
        window->startExport(settings);
        ASSERT_TRUE(finished.wait(kRenderTimeoutMs));
        ASSERT_EQ(finished.count(), 1);
        EXPECT_FALSE(finished[0][0].toBool());
        const std::string message = finished[0][1].toString().toStdString();
        EXPECT_NE(message.find(fs::path(path).filename().string()), std::string::npos) << message;
        EXPECT_NE(message.find(expected), std::string::npos) << message;
    }
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"full.png", "seed.json"}));
    EXPECT_TRUE(fs::is_character_file("/dev/full"));
    EXPECT_EQ(doc->scene(), before);
    EXPECT_FALSE(doc->isModified());
}

// The largest render the format allows: the editor starts it, shows
// its first frame, and the next edit cancels it at once; the small scene's
// render then arrives whole. Figures printed, bounds generous.
TEST_F(MainWindowTest, LargestScene_FirstFrameThenAnEditCancelsItAtOnce) {
    using Clock = std::chrono::steady_clock;
    const size_t shown = log->generations.size();
    const Clock::time_point start = Clock::now();
    ASSERT_TRUE(doc->edit("huge", [](Scene& s) {
        s.render.width = kMaxImageSize;
        s.render.height = kMaxImageSize;
        s.render.samplesPerPixel = kMaxSamplesPerPixel;
    }));
    ASSERT_TRUE(QTest::qWaitFor([&] { return log->generations.size() > shown; }, kRenderTimeoutMs))
        << "no frame of the 16384x16384 render";
    const double firstFrame = std::chrono::duration<double>(Clock::now() - start).count();
    // The view renders at most kMaxViewSize on the long side, whatever the scene says.
    EXPECT_EQ(log->lastCovers, QSize(kMaxViewSize, kMaxViewSize));
    Scene wide = doc->scene();
    wide.render.width = 16384;
    wide.render.height = 3;
    EXPECT_EQ(viewSized(wide).render.width, kMaxViewSize);
    EXPECT_EQ(viewSized(wide).render.height, 1);
    EXPECT_EQ(viewSized(doc->scene()).render.width, kMaxViewSize);
    const int before = log->completed;
    const Clock::time_point edit = Clock::now();
    ASSERT_TRUE(doc->edit("small", [](Scene& s) {
        s.render.width = kWidth;
        s.render.height = kHeight;
        s.render.samplesPerPixel = 1;
    }));
    ASSERT_TRUE(waitForRender(before));
    const double toSmall = std::chrono::duration<double>(Clock::now() - edit).count();
    std::cout << "[ FIGURES  ] first frame of 16384x16384 after " << firstFrame
              << " s; the small scene complete " << toSmall << " s after the edit\n";
    EXPECT_LT(toSmall, 5.0);
    EXPECT_TRUE(sameImage(view->frame(), coreRender(doc->scene())));
}

// Stress: thousands of random edits, undos and redos as fast as the
// GUI thread can make them while the worker renders (events processed after
// each, so renders start and are abandoned all the time). Nothing crashes or
// hangs, and once the edits stop the view shows exactly a fresh render of the
// final scene. The seed is printed and WHITTED_TEST_SEED replays it.
TEST_F(MainWindowTest, Stress_RandomEditsUndoRedoWhileRendering_FinalViewIsFreshRender) {
    const unsigned seed = qEnvironmentVariableIsSet("WHITTED_TEST_SEED")
                              ? qEnvironmentVariable("WHITTED_TEST_SEED").toUInt()
                              : 20261122u;
    std::cout << "[ SEED     ] WHITTED_TEST_SEED=" << seed << "\n";
    std::mt19937 rng(seed);
    auto uniform = [&](double a, double b) {
        return std::uniform_real_distribution<double>(a, b)(rng);
    };
    auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
    constexpr int kSteps = 3000;
    int edits = 0, undos = 0, redos = 0, refused = 0;
    const auto start = std::chrono::steady_clock::now();
    for (int step = 0; step < kSteps; ++step) {
        QUndoStack* undo = doc->undoStack();
        const int action = pick(12);
        bool ok = true;
        if (action == 0 && undo->canUndo()) {
            undo->undo();
            ++undos;
        } else if ((action == 1 || action == 2) && undo->canRedo()) {
            undo->redo();
            ++redos;
        } else {
            const int kind = pick(8);
            ok = doc->edit("stress", [&](Scene& s) {
                const int n = int(s.spheres.size());
                switch (kind) {
                    case 0:
                        s.spheres[pick(n)].radius = uniform(0.05, 1.0);
                        break;
                    case 1:
                        s.spheres[pick(n)].center +=
                            Vec3(uniform(-0.2, 0.2), uniform(-0.2, 0.2), uniform(-0.2, 0.2));
                        break;
                    case 2:
                        s.materials[pick(int(s.materials.size()))].diffuse =
                            Vec3(uniform(0, 1), uniform(0, 1), uniform(0, 1));
                        break;
                    case 3:
                        s.lights[0].position =
                            Vec3(uniform(-10, 10), uniform(1, 10), uniform(-10, 0));
                        break;
                    case 4:
                        s.camera = orbit(s.camera, uniform(-0.2, 0.2), uniform(-0.1, 0.1));
                        break;
                    case 5:
                        if (n < 12)
                            s.spheres.push_back(
                                Sphere{"extra " + std::to_string(step),
                                       {uniform(-2, 2), uniform(0, 1), uniform(1, 5)},
                                       uniform(0.1, 0.5),
                                       s.materials[pick(int(s.materials.size()))].name});
                        break;
                    case 6:
                        if (n > 2)
                            s.spheres.erase(s.spheres.begin() +
                                            pick(n - 1));  // the floor stays last
                        break;
                    default:
                        s.render.samplesPerPixel = 1 + pick(3);
                        s.render.maxDepth = pick(5);
                        s.render.precision = pick(2) ? Precision::Float : Precision::Double;
                }
            });
            ++edits;
        }
        refused += !ok;
        QCoreApplication::processEvents();
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << "[ FIGURES  ] " << edits << " edits (" << refused << " refused), " << undos
              << " undos, " << redos << " redos in " << seconds << " s\n";
    // One last edit with no events processed before it: only its frames can
    // reach the view from here on.
    const int before = log->completed;
    ASSERT_TRUE(doc->edit("last", [](Scene& s) { s.spheres[0].radius = 0.42; }));
    ASSERT_TRUE(waitForRender(before));
    EXPECT_TRUE(sameImage(view->frame(), coreRender(doc->scene())));
    EXPECT_EQ(refused, 0);
}

}  // namespace
}  // namespace whitted::ui
