// Copy and paste of spheres between editor windows, through the system
// clipboard, driven as a user drives it: clicks in the picture and Ctrl+C /
// Ctrl+V sent to the window that is active. The pasted spheres keep their
// centres, radii and materials bit for bit, are renamed when their names are
// taken, bring their materials along, and are one undo step; anything else on
// the clipboard is refused with a message and pastes nothing.
#include <QClipboard>
#include <QGuiApplication>
#include <QMessageBox>

#include <algorithm>
#include <string>
#include <vector>

#include "scene/scene_fragment.h"

#include "support/main_window_fixture.h"

namespace whitted::ui {
namespace {

class ClipboardTest : public MainWindowTest {
  protected:
    void TearDown() override {
        second.reset();
        MainWindowTest::TearDown();
    }

    // A second editor window, shown beside the first, on File > New's scene.
    ::testing::AssertionResult showSecondWindow() {
        second = std::make_unique<MainWindow>();
        second->resize(1200, 800);
        second->show();
        if (!QTest::qWaitForWindowExposed(second.get()))
            return ::testing::AssertionFailure() << "the second window was never exposed";
        if (auto active = activate(*second); !active) return active;
        key(*second, Qt::Key_N, Qt::ControlModifier);
        return ::testing::AssertionSuccess();
    }

    // The window the user turns to: its shortcuts are the ones that act.
    static ::testing::AssertionResult activate(MainWindow& w) {
        w.activateWindow();
        if (QTest::qWaitForWindowActive(&w)) return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << "the window never became active";
    }
    static void key(MainWindow& w, Qt::Key k, Qt::KeyboardModifiers modifiers = {}) {
        QTest::keyClick(w.windowHandle(), k, modifiers);
    }

    // Clicks (Shift: Shift+clicks) a sphere's drawn centre in the first window's view.
    void clickSphere(int index, Qt::KeyboardModifiers modifiers = {}) {
        const QRect r = view->imageRect();
        const QPointF image = project(doc->scene(), doc->scene().spheres[index].center);
        const QPoint at(int(r.left() + image.x() * r.width() / kWidth),
                        int(r.top() + image.y() * r.height() / kHeight));
        QTest::mouseClick(window->windowHandle(), Qt::LeftButton, modifiers,
                          view->mapTo(window.get(), at));
    }
    // The blue and purple balls selected in the first window, and Ctrl+C.
    void copyBlueAndPurple() {
        ASSERT_TRUE(activate(*window));
        clickSphere(kBlueBall);
        clickSphere(kPurpleBall, Qt::ShiftModifier);
        ASSERT_EQ(doc->selection()->indices(), (std::vector<int>{kBlueBall, kPurpleBall}));
        key(*window, Qt::Key_C, Qt::ControlModifier);
        ASSERT_TRUE(QGuiApplication::clipboard()->text().contains("whitted-scene-fragment"))
            << QGuiApplication::clipboard()->text().toStdString();
    }

    // The message box a window opened to tell the user something; nullptr when none.
    static QMessageBox* openMessage(MainWindow& w) {
        for (QMessageBox* box : w.findChildren<QMessageBox*>())
            if (box->isVisible()) return box;
        return nullptr;
    }

    // Ctrl+V in the first window with `text` on the clipboard: refused, nothing pasted.
    // The message names the clipboard, and `mentions` too.
    void expectPasteRefused(const QString& text, const QString& mentions = {}) {
        QGuiApplication::clipboard()->setText(text);
        ASSERT_TRUE(activate(*window));
        const Scene before = doc->scene();
        const int steps = doc->undoStack()->count();
        key(*window, Qt::Key_V, Qt::ControlModifier);
        EXPECT_EQ(doc->scene(), before);
        EXPECT_EQ(doc->undoStack()->count(), steps);
        EXPECT_FALSE(doc->isModified());
        const QString error = window->lastError();
        EXPECT_TRUE(error.contains("clipboard", Qt::CaseInsensitive)) << error.toStdString();
        EXPECT_TRUE(error.contains(mentions)) << error.toStdString();
        QMessageBox* box = openMessage(*window);
        ASSERT_NE(box, nullptr) << "the refusal is shown";
        EXPECT_EQ(box->text(), error);
        box->close();
    }

    std::unique_ptr<MainWindow> second;
};

TEST_F(ClipboardTest, CopyInOneWindow_PasteInAnother_SameSpheresTheirMaterialsOneStep) {
    ASSERT_TRUE(showSecondWindow());
    SceneDocument* other = second->document();
    const Scene fresh = other->scene();
    ASSERT_EQ(fresh, MainWindow::newSceneTemplate());
    copyBlueAndPurple();

    ASSERT_TRUE(activate(*second));
    const int steps = other->undoStack()->count();
    key(*second, Qt::Key_V, Qt::ControlModifier);

    const Scene& from = doc->scene();
    const Scene& into = other->scene();
    ASSERT_EQ(into.spheres.size(), fresh.spheres.size() + 2);
    for (std::size_t i = 0; i < fresh.spheres.size(); ++i)
        EXPECT_EQ(into.spheres[i], fresh.spheres[i]);
    const std::vector<int> copied = {kBlueBall, kPurpleBall};
    for (std::size_t k = 0; k < copied.size(); ++k) {
        const Sphere& original = from.spheres[copied[k]];
        const Sphere& pasted = into.spheres[fresh.spheres.size() + k];
        EXPECT_EQ(pasted.name, original.name) << "not taken there";
        EXPECT_EQ(pasted.center, original.center) << original.name;
        EXPECT_EQ(pasted.radius, original.radius) << original.name;
        EXPECT_EQ(pasted.material, original.material) << original.name;
        const auto sameName = [&](const Material& m) { return m.name == original.material; };
        const auto theirs = std::find_if(from.materials.begin(), from.materials.end(), sameName);
        const auto ours = std::find_if(into.materials.begin(), into.materials.end(), sameName);
        ASSERT_NE(theirs, from.materials.end());
        ASSERT_NE(ours, into.materials.end()) << original.material << " came along";
        EXPECT_EQ(*ours, *theirs);
    }
    EXPECT_EQ(into.materials.size(), fresh.materials.size() + 2) << "blue and purple added";
    EXPECT_EQ(other->selection()->kind(), ItemKind::Sphere);
    EXPECT_EQ(other->selection()->indices(), (std::vector<int>{2, 3})) << "the pasted spheres";
    EXPECT_EQ(other->undoStack()->count(), steps + 1);
    EXPECT_EQ(doc->undoStack()->count(), 0) << "the first window is untouched";

    other->undoStack()->undo();
    EXPECT_EQ(other->scene(), fresh);
}

TEST_F(ClipboardTest, PasteIntoTheSameWindow_RenamesTheCopies_ReusesTheMaterials) {
    copyBlueAndPurple();
    const Scene before = doc->scene();
    key(*window, Qt::Key_V, Qt::ControlModifier);

    const Scene& s = doc->scene();
    ASSERT_EQ(s.spheres.size(), before.spheres.size() + 2);
    // scene_fragment.h: a name the scene has is renamed "ball" -> "ball 2".
    const Sphere& blue = s.spheres[before.spheres.size()];
    const Sphere& purple = s.spheres[before.spheres.size() + 1];
    EXPECT_EQ(blue.name, "blue ball 2");
    EXPECT_EQ(purple.name, "purple ball 2");
    EXPECT_EQ(blue.center, before.spheres[kBlueBall].center);
    EXPECT_EQ(blue.radius, before.spheres[kBlueBall].radius);
    EXPECT_EQ(purple.center, before.spheres[kPurpleBall].center);
    EXPECT_EQ(purple.radius, before.spheres[kPurpleBall].radius);
    EXPECT_EQ(blue.material, "blue") << "the same material, reused";
    EXPECT_EQ(purple.material, "purple");
    EXPECT_EQ(s.materials, before.materials);
    EXPECT_EQ(doc->selection()->indices(),
              (std::vector<int>{int(before.spheres.size()), int(before.spheres.size()) + 1}));
    EXPECT_EQ(doc->undoStack()->count(), 1);
    doc->undoStack()->undo();
    EXPECT_EQ(doc->scene(), before);
}

TEST_F(ClipboardTest, PlainText_RefusedWithAMessage_NothingPasted) {
    expectPasteRefused(QStringLiteral("hello"));
}

TEST_F(ClipboardTest, FragmentWithANegativeRadius_RefusedWithAMessage_NothingOfItPasted) {
    // The blue and purple balls as Ctrl+C writes them, the purple one's radius
    // made negative: the blue one must not be pasted either.
    Scene source = doc->scene();
    source.spheres[kPurpleBall].radius = 0.4375;
    QString text = QString::fromStdString(fragmentToJson(source, {kBlueBall, kPurpleBall}, {}));
    ASSERT_EQ(text.count(QStringLiteral("0.4375")), 1) << text.toStdString();
    text.replace(QStringLiteral("0.4375"), QStringLiteral("-0.4375"));
    expectPasteRefused(text, QStringLiteral("radius"));
}

}  // namespace
}  // namespace whitted::ui
