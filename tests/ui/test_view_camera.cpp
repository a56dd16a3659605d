// The render view as a newcomer uses it: orbit about
// what is under the cursor, keys and mouse turning the same way, a wheel that
// zooms towards the cursor and never passes it, a run of camera moves as one
// undo step, the selection outlined, lights drawn and clickable, and the name of
// what is under the cursor. Driven through the shown window's keys and mouse;
// positions are checked against core's projection, pictures against core's render.
#include <QApplication>
#include <QPainter>
#include <QTest>
#include <QUndoStack>
#include <QWheelEvent>

#include <glm/geometric.hpp>

#include <cmath>
#include <optional>

#include "camera/camera_control.h"
#include "panels/scene_panel.h"
#include "support/main_window_fixture.h"
#include "viewport/view_overlay.h"

namespace whitted::ui {
namespace {

constexpr double kPixelTolerance = 1e-6;
const QColor kSelectionColour(255, 160, 30);  // view_overlay.cpp's colour for "selected"

class ViewCameraTest : public MainWindowTest {
  protected:
    // The surface point seen at a widget point, as the view finds it.
    std::optional<Vec3> surfaceAtWidget(QPointF widget) const {
        const QPointF image = imagePoint(doc->scene(), view->imageRect(), widget);
        const auto pick = pickSurface(doc->scene(), image.x(), image.y());
        if (!pick) return std::nullopt;
        return pick->point;
    }

    // What the arrow keys turn about in a fresh view: the surface at its centre.
    Vec3 centrePivot() const {
        return surfaceAtWidget(QPointF(view->imageRect().center()) + QPointF(0.5, 0.5)).value();
    }

    void expectSameImagePoint(const Vec3& p, const Camera& before, const Camera& after) const {
        const auto a = projectToImage(before, kWidth, kHeight, p);
        const auto b = projectToImage(after, kWidth, kHeight, p);
        ASSERT_TRUE(a && b);
        EXPECT_NEAR(a->x, b->x, kPixelTolerance);
        EXPECT_NEAR(a->y, b->y, kPixelTolerance);
    }

    void drag(QPoint from, QPoint by) {
        QTest::mousePress(view, Qt::LeftButton, {}, from);
        for (int i = 1; i <= 10; ++i) QTest::mouseMove(view, from + by * i / 10);
        QTest::mouseRelease(view, Qt::LeftButton, {}, from + by);
    }

    void wheel(QPoint at, int ticks) {
        QWheelEvent e(QPointF(at), view->mapToGlobal(QPointF(at)), {}, {0, 120 * ticks},
                      Qt::NoButton, {}, Qt::NoScrollPhase, false);
        QApplication::sendEvent(view, &e);
    }

    // The view as shown, and the picture alone drawn as the view draws it:
    // where they differ is what the view draws over the picture.
    QImage shown() const { return view->grab().toImage().convertToFormat(QImage::Format_RGB32); }
    QImage pictureAlone() const {
        QImage picture(view->size(), QImage::Format_RGB32);
        QPainter painter(&picture);
        painter.fillRect(picture.rect(), QColor(45, 45, 48));
        painter.drawImage(view->imageRect(), view->frame());
        return picture;
    }
    // Pixels of the overlay within `radius` of widget point `at` (everywhere by default).
    int overlayPixels(QPoint at = {}, int radius = 1 << 20) const {
        const QImage a = shown(), b = pictureAlone();
        int n = 0;
        for (int y = 0; y < a.height(); ++y)
            for (int x = 0; x < a.width(); ++x)
                n += std::abs(x - at.x()) <= radius && std::abs(y - at.y()) <= radius &&
                     a.pixel(x, y) != b.pixel(x, y);
        return n;
    }
    // Pixels of the view as shown in exactly this colour.
    int shownPixels(QColor colour) const {
        const QImage a = shown();
        int n = 0;
        for (int y = 0; y < a.height(); ++y)
            for (int x = 0; x < a.width(); ++x) n += a.pixel(x, y) == colour.rgb();
        return n;
    }
};

// The arrow turns about the surface at the view's centre, which stays put.
TEST_F(ViewCameraTest, ArrowKey_Left_OrbitsFiveDegreesAboutWhatIsAtTheCentre) {
    const Camera before = doc->scene().camera;
    const Vec3 pivot = centrePivot();
    const QImage image = view->frame();
    const int n = log->completed;
    QTest::keyClick(view, Qt::Key_Left);
    ASSERT_TRUE(waitForRender(n));

    const Camera after = doc->scene().camera;
    EXPECT_EQ(after, orbitAbout(before, pivot, kPi / 36, 0));
    expectSameImagePoint(pivot, before, after);
    const Vec3 a = before.position - pivot, b = after.position - pivot;
    EXPECT_NEAR(glm::length(b), glm::length(a), 1e-12);
    EXPECT_NEAR(b.y, a.y, 1e-12);  // yaw about the vertical: the height stays
    const double turned = std::atan2(b.z, b.x) - std::atan2(a.z, a.x);
    EXPECT_NEAR(std::abs(turned) * 180 / kPi, 5.0, 1e-9);
    EXPECT_EQ(doc->undoStack()->count(), 1);
    EXPECT_FALSE(identical(view->frame(), image));
    EXPECT_TRUE(sameImage(view->frame(), coreRender(doc->scene())));
}

// One direction for keys and mouse: up raises the eye, left takes it left.
TEST_F(ViewCameraTest, UpAndLeft_KeyAndDragTurnTheSameWay) {
    const Scene start = doc->scene();
    const QPoint centre = view->imageRect().center();
    auto eyeMove = [&](auto act) {
        doc->reset(start, doc->filePath());
        act();
        return doc->scene().camera.position - start.camera.position;
    };
    const Vec3 upKey = eyeMove([&] { QTest::keyClick(view, Qt::Key_Up); });
    const Vec3 upDrag = eyeMove([&] { drag(centre, QPoint(0, -30)); });
    EXPECT_GT(upKey.y, 0.0);
    EXPECT_GT(upDrag.y, 0.0);
    // The eye looks along +z: its left is -x.
    const Vec3 leftKey = eyeMove([&] { QTest::keyClick(view, Qt::Key_Left); });
    const Vec3 leftDrag = eyeMove([&] { drag(centre, QPoint(-30, 0)); });
    EXPECT_LT(leftKey.x, 0.0);
    EXPECT_LT(leftDrag.x, 0.0);
}

// A drag turns about the point grabbed, which stays under the cursor's
// start; a mark shows the pivot while dragging; the drag is one undo step.
TEST_F(ViewCameraTest, Drag_OrbitsAboutTheGrabbedPointWithAMarkAsOneUndoStep) {
    window->scenePanel()->select(ItemKind::Sphere, -1);
    const Camera before = doc->scene().camera;
    const QImage image = view->frame();
    const QPoint grab =
        widgetPoint(project(doc->scene(), doc->scene().spheres[kPurpleBall].center));
    const Vec3 pivot = surfaceAtWidget(grab).value();
    const int n = log->completed;

    QTest::mousePress(view, Qt::LeftButton, {}, grab);
    for (int i = 1; i <= 10; ++i) QTest::mouseMove(view, grab + QPoint(4 * i, 2 * i));
    // The mark: rings and cross lines drawn over the picture at the pivot,
    // which stays under the point grabbed.
    const int markWhileDragging = overlayPixels(grab, 10);
    QTest::mouseRelease(view, Qt::LeftButton, {}, grab + QPoint(40, 20));
    ASSERT_TRUE(waitForRender(n));
    EXPECT_GT(markWhileDragging, 40);
    EXPECT_EQ(overlayPixels(grab, 10), 0) << "the pivot mark stays after the drag";

    const Camera after = doc->scene().camera;
    expectSameImagePoint(pivot, before, after);
    EXPECT_NEAR(glm::length(after.position - pivot), glm::length(before.position - pivot), 1e-9);
    EXPECT_EQ(doc->undoStack()->count(), 1);
    ASSERT_TRUE(undoAndWait());
    EXPECT_EQ(doc->scene().camera, before);
    EXPECT_TRUE(sameImage(view->frame(), image));
}

// After F, orbiting keeps the sphere in the
// middle of the picture instead of sweeping it out of the frame.
TEST_F(ViewCameraTest, FrameThenArrows_TheSphereStaysInTheMiddle) {
    window->scenePanel()->select(ItemKind::Sphere, kBlueBall);
    QTest::keyClick(view, Qt::Key_F);
    for (int i = 0; i < 9; ++i) QTest::keyClick(view, Qt::Key_Left);  // 45 degrees
    for (int i = 0; i < 4; ++i) QTest::keyClick(view, Qt::Key_Up);
    const Vec3 centre = doc->scene().spheres[kBlueBall].center;
    const auto seen = projectToImage(doc->scene().camera, kWidth, kHeight, centre);
    ASSERT_TRUE(seen.has_value());
    EXPECT_NEAR(seen->x, kWidth / 2.0, kPixelTolerance);
    EXPECT_NEAR(seen->y, kHeight / 2.0, kPixelTolerance);
}

// The wheel moves towards what is under the cursor, which stays under
// it, and however far it is turned never reaches or passes it.
TEST_F(ViewCameraTest, Wheel_DolliesTowardsTheCursorAndNeverPassesIt) {
    const Camera before = doc->scene().camera;
    const QPoint at = widgetPoint(project(doc->scene(), doc->scene().spheres[kPurpleBall].center));
    const Vec3 target = surfaceAtWidget(at).value();
    wheel(at, 1);
    const Camera once = doc->scene().camera;
    expectSameImagePoint(target, before, once);
    EXPECT_NEAR(glm::length(once.position - target), 0.9 * glm::length(before.position - target),
                1e-12);
    for (int i = 0; i < 200; ++i) wheel(at, 1);
    const Vec3 forward = before.lookAt - before.position;
    EXPECT_GT(glm::dot(target - doc->scene().camera.position, forward), 0.0);
    // Within half a second of each other, the ticks were one undo step.
    EXPECT_EQ(doc->undoStack()->count(), 1);
}

// A run of camera moves is one step; a pause, or an undo, starts another.
TEST_F(ViewCameraTest, CameraRun_KeysWithinHalfASecondAreOneUndoStep) {
    const Camera start = doc->scene().camera;
    QUndoStack* undo = doc->undoStack();
    for (int i = 0; i < 5; ++i) QTest::keyClick(view, Qt::Key_Left);
    EXPECT_EQ(undo->count(), 1);
    EXPECT_EQ(undo->undoText(), QStringLiteral("Orbit camera"));
    // Another kind of move in the same run: W walks in fly mode (Shift+`).
    QTest::keyClick(view, Qt::Key_AsciiTilde, Qt::ShiftModifier);
    ASSERT_TRUE(view->flying());
    QTest::keyClick(view, Qt::Key_W);
    EXPECT_EQ(undo->count(), 1);
    EXPECT_EQ(undo->undoText(), QStringLiteral("Move camera"));
    const Camera afterRun = doc->scene().camera;

    QTest::qWait(SceneDocument::kRunGapMs + 200);
    QTest::keyClick(view, Qt::Key_Left);
    EXPECT_EQ(undo->count(), 2);
    undo->undo();
    EXPECT_EQ(doc->scene().camera, afterRun);
    QTest::keyClick(view, Qt::Key_Right);  // at once after the undo: still a step of its own
    EXPECT_EQ(undo->count(), 2);
    undo->undo();
    undo->undo();
    EXPECT_EQ(doc->scene().camera, start);  // the whole first run in one undo
    EXPECT_FALSE(doc->isModified());

    // An undo of anything closes the run, however quick the next move.
    QTest::keyClick(view, Qt::Key_Left);
    doc->edit(QStringLiteral("Radius"), [](Scene& s) { s.spheres[kBlueBall].radius = 0.5; });
    undo->undo();
    QTest::keyClick(view, Qt::Key_Left);
    EXPECT_EQ(undo->count(), 2);
}

// The selected sphere is outlined where its silhouette is, and only then.
TEST_F(ViewCameraTest, SelectedSphere_IsOutlinedAtItsSilhouette) {
    const Scene& s = doc->scene();
    const Sphere& ball = s.spheres[kPurpleBall];
    // Around the ball: its outline and a few pixels more (the light's marker is elsewhere).
    const QPoint middle = widgetPoint(project(s, ball.center));
    const int around = widgetPoint({kWidth / 5.0, 0}).x() - widgetPoint({0, 0}).x();
    window->scenePanel()->select(ItemKind::Sphere, -1);
    EXPECT_EQ(overlayPixels(middle, around), 0);
    window->scenePanel()->select(ItemKind::Sphere, kPurpleBall);
    const auto outline = sphereOutline(s.camera, kWidth, kHeight, ball.center, ball.radius);
    ASSERT_EQ(outline.size(), 1u);
    int checked = 0, onOutline = 0;
    for (std::size_t k = 0; k < outline.front().size(); k += 8, ++checked) {
        const ImagePoint p = outline.front()[k];
        onOutline += overlayPixels(widgetPoint({p.x, p.y}), 2) > 0;
    }
    EXPECT_EQ(onOutline, checked) << "points of the silhouette with the outline drawn on them";
    EXPECT_GT(shownPixels(kSelectionColour), 100);
    // Not at the ball's middle: an outline, not a fill.
    EXPECT_EQ(overlayPixels(middle, 5), 0);
    window->scenePanel()->select(ItemKind::Sphere, -1);
    EXPECT_EQ(overlayPixels(middle, around), 0);
}

// A light in view is drawn as a marker; a click on it selects the light,
// which is then ringed; hovering names what is under the cursor.
TEST_F(ViewCameraTest, LightMarker_ShownClickableAndNamedOnHover) {
    ASSERT_TRUE(editAndWait([](Scene& s) {
        s.lights.push_back(Light{"fill", {0.3, 0.9, 3}, {1, 0.5, 0}, 0.5});
    }));
    const int fill = int(doc->scene().lights.size()) - 1;
    const QPoint marker = widgetPoint(project(doc->scene(), doc->scene().lights[fill].position));
    window->scenePanel()->select(ItemKind::Sphere, -1);
    EXPECT_GT(shownPixels(QColor::fromRgbF(1, 0.5, 0)), 50) << "no marker in the light's colour";
    EXPECT_GT(overlayPixels(marker, 12), 150);

    QTest::mouseMove(view, marker);
    EXPECT_EQ(view->hoverText(), QStringLiteral("fill (light)"));
    const QPoint ball =
        widgetPoint(project(doc->scene(), doc->scene().spheres[kPurpleBall].center));
    QTest::mouseMove(view, ball);
    EXPECT_EQ(view->hoverText(), QStringLiteral("purple ball (sphere)"));
    QTest::mouseMove(view, view->imageRect().topLeft() + QPoint(2, 2));  // the sky
    EXPECT_EQ(view->hoverText(), QString());

    EXPECT_EQ(shownPixels(kSelectionColour), 0);
    QTest::mouseClick(view, Qt::LeftButton, {}, marker);
    EXPECT_EQ(window->scenePanel()->currentKind(), ItemKind::Light);
    EXPECT_EQ(window->scenePanel()->currentIndex(), fill);
    EXPECT_GT(shownPixels(kSelectionColour), 10) << "the selected light is not ringed";
    EXPECT_EQ(doc->undoStack()->count(), 1);  // the click picks, it does not edit
}

// The seed's light is behind the camera, up and to the right: its marker
// waits at the picture's top-right edge, and a click there selects it.
TEST_F(ViewCameraTest, LightOutsideThePicture_MarkedAtTheEdgeTowardsIt) {
    window->scenePanel()->select(ItemKind::Sphere, -1);
    const QRect r = view->imageRect();
    const QImage a = shown(), b = pictureAlone();
    QPoint sum;
    int n = 0;
    for (int y = r.top(); y <= r.bottom(); ++y)
        for (int x = r.left(); x <= r.right(); ++x)
            if (a.pixel(x, y) != b.pixel(x, y)) {
                sum += QPoint(x, y);
                ++n;
            }
    ASSERT_GT(n, 100) << "no marker drawn for the light behind the camera";
    const QPoint marker = sum / n;
    // Light (5, 5, -10) from the eye (0, 0.35, -1) looking along +z: right and up.
    EXPECT_GT(marker.x(), r.center().x());
    EXPECT_LT(marker.y(), r.center().y());
    EXPECT_TRUE(marker.x() > r.right() - 40 || marker.y() < r.top() + 40)
        << "the marker is not at the edge: " << marker.x() << ", " << marker.y();
    QTest::mouseClick(view, Qt::LeftButton, {}, marker);
    EXPECT_EQ(window->scenePanel()->currentKind(), ItemKind::Light);
    EXPECT_EQ(window->scenePanel()->currentIndex(), 0);
}

// On a scene of 20,000 balls, moving one ball and orbiting the camera refit
// the render worker's tree instead of building one (the build is the costly
// part of an edit at this size), a new material uses it as it is, and the
// view shows exactly the core's own render of the edited scene.
TEST_F(ViewCameraTest, LargeScene_MoveAndOrbit_RefitTheTreeAndShowTheExactPicture) {
    ASSERT_TRUE(editAndWait([](Scene& s) {
        for (int i = 0; i < 20000; ++i)
            s.spheres.push_back({"grain " + std::to_string(i),
                                 {-3.0 + 0.03 * (i % 200), -0.45, 1.0 + 0.05 * (i / 200)},
                                 0.012,
                                 i % 2 ? "blue" : "purple"});
    }));
    const RenderWorker& worker = window->renderWorker();
    const int builds = worker.bvhBuilds(), refits = worker.bvhRefits();
    ASSERT_GE(builds, 1);

    ASSERT_TRUE(editAndWait([](Scene& s) { s.spheres[kBlueBall].center.x += 0.2; }));
    EXPECT_EQ(worker.bvhBuilds(), builds);
    EXPECT_EQ(worker.bvhRefits(), refits + 1);
    EXPECT_TRUE(sameImage(view->frame(), coreRender(doc->scene())));

    // A material moves nothing: the tree is used as it is.
    const int reuses = worker.bvhReuses();
    ASSERT_TRUE(editAndWait([](Scene& s) {
        for (std::size_t i = 4; i < s.spheres.size(); i += 3) s.spheres[i].material = "white";
    }));
    EXPECT_EQ(worker.bvhRefits(), refits + 1);
    EXPECT_EQ(worker.bvhReuses(), reuses + 1);
    EXPECT_TRUE(sameImage(view->frame(), coreRender(doc->scene())));

    const int before = log->completed;
    view->setFocus();
    QTest::keyClick(view, Qt::Key_Left);
    ASSERT_TRUE(waitForRender(before));
    EXPECT_EQ(worker.bvhBuilds(), builds) << "an orbit moves every sphere of the camera's frame";
    EXPECT_EQ(worker.bvhRefits(), refits + 2);
    EXPECT_EQ(worker.bvhReuses(), reuses + 1);
    EXPECT_TRUE(sameImage(view->frame(), coreRender(doc->scene())));
}

}  // namespace
}  // namespace whitted::ui
