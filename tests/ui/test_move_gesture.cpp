// Moving a sphere in the view with the mouse (G, as in Blender), driven as a
// user drives it: mouse and key events sent to the shown window, never to the
// view directly. The sphere follows the pointer, axes and typed numbers
// constrain it, Ctrl snaps, Escape puts it back bit for bit, and each move is
// one undo step that the saved file holds.
#include <QInputDialog>
#include <QLabel>
#include <QPointer>
#include <QSettings>
#include <QStatusBar>

#include "panels/scene_panel.h"

#include "support/window_events.h"

namespace whitted::ui {
namespace {

class ViewMoveTest : public WindowEventsTest {
  protected:
    // Where the blue ball's centre is drawn in the view.
    QPointF drawnCentre() const { return drawn(ball().center); }
    const Sphere& ball() const { return doc->scene().spheres[kBlueBall]; }

    // Clicks the blue ball to select it and leaves the pointer on its centre.
    QPoint selectBall() {
        const QPoint centre = drawnCentre().toPoint();
        QTest::mouseClick(shownWindow(), Qt::LeftButton, {}, inWindow(centre));
        QTest::mouseMove(shownWindow(), inWindow(centre));
        return centre;
    }
};

TEST_F(ViewMoveTest, G_ThenMouse_TheBallFollowsThePointer_OneUndoStepTheFileKeeps) {
    const Vec3 start = ball().center;
    const QPoint grab = selectBall();
    ASSERT_EQ(window->scenePanel()->currentIndex(), int(kBlueBall));
    const QPointF before = drawnCentre();
    const int steps = doc->undoStack()->count();

    key(Qt::Key_G);
    EXPECT_TRUE(view->moving());
    EXPECT_TRUE(window->statusBar()->currentMessage().contains("Move blue ball"))
        << window->statusBar()->currentMessage().toStdString();
    const QPoint by(60, -25);
    movePointer(grab, grab + by);
    click(grab + by);
    EXPECT_FALSE(view->moving());

    // The outline (and the centre it is drawn round) moved with the pointer.
    const QPointF moved = drawnCentre() - before;
    EXPECT_NEAR(moved.x(), by.x(), 2);
    EXPECT_NEAR(moved.y(), by.y(), 2);
    // In the plane facing the camera: as deep as it was.
    const Camera& c = doc->scene().camera;
    const Vec3 forward = glm::normalize(c.lookAt - c.position);
    EXPECT_NEAR(glm::dot(ball().center - c.position, forward),
                glm::dot(start - c.position, forward), 1e-9);
    EXPECT_EQ(doc->undoStack()->count(), steps + 1);
    EXPECT_EQ(doc->undoStack()->undoText(), QString("Move blue ball"));

    // The picture shows it where it is.
    const QImage expected = coreRender(doc->scene());
    if (!QTest::qWaitFor([&] { return identical(view->frame(), expected); }, kRenderTimeoutMs)) {
        EXPECT_TRUE(sameImage(view->frame(), expected));
    }

    // Saved, the file holds the moved centre; undo and redo take it back and forth.
    const Vec3 after = ball().center;
    key(Qt::Key_S, Qt::ControlModifier);
    EXPECT_EQ(loadScene(scenePath.toStdString()).spheres[kBlueBall].center, after);
    doc->undoStack()->undo();
    EXPECT_EQ(ball().center, start);
    doc->undoStack()->redo();
    EXPECT_EQ(ball().center, after);
}

TEST_F(ViewMoveTest, G_X_Typed2_Enter_MovesExactlyTwoAlongX_MinusTypedMovesBack) {
    const Vec3 start = ball().center;
    selectBall();
    key(Qt::Key_G);
    key(Qt::Key_X);
    key(Qt::Key_2);
    key(Qt::Key_Return);
    EXPECT_EQ(ball().center, start + Vec3(2, 0, 0));

    key(Qt::Key_G);
    key(Qt::Key_Z);
    key(Qt::Key_Minus);
    key(Qt::Key_1);
    key(Qt::Key_Period);
    key(Qt::Key_5);
    key(Qt::Key_Return);
    EXPECT_EQ(ball().center, start + Vec3(2, 0, 0) + Vec3(0, 0, -1.5));
    EXPECT_EQ(doc->undoStack()->undoText(), QString("Move blue ball"));
}

TEST_F(ViewMoveTest, G_Y_ThenMouse_MovesAlongYAlone) {
    const Vec3 start = ball().center;
    const QPoint grab = selectBall();
    key(Qt::Key_G);
    key(Qt::Key_Y);
    movePointer(grab, grab + QPoint(30, -40));
    key(Qt::Key_Return);
    EXPECT_EQ(ball().center.x, start.x);
    EXPECT_EQ(ball().center.z, start.z);
    EXPECT_GT(ball().center.y, start.y + 0.1) << "up the screen is up the y axis";
}

TEST_F(ViewMoveTest, CtrlWhileMoving_SnapsTheOffsetToTheGrid) {
    const Vec3 start = ball().center;
    const QPoint grab = selectBall();
    key(Qt::Key_G);
    movePointer(grab, grab + QPoint(47, 13), Qt::ControlModifier);
    click(grab + QPoint(47, 13));
    expectOnGrid(ball().center - start, RenderView::kMoveGrid);
}

// View > Snap Step sets the grid Ctrl snaps to, and the next start keeps it.
TEST_F(ViewMoveTest, SnapStepSetInTheViewMenu_CtrlSnapsToIt_AndItIsRemembered) {
    window->findChild<QAction*>(QStringLiteral("snapStep"))->trigger();
    QPointer<QInputDialog> dialog =
        window->findChild<QInputDialog*>(QStringLiteral("snapStepDialog"));
    ASSERT_NE(dialog, nullptr);
    dialog->setDoubleValue(0.25);
    dialog->accept();
    // Closed, it gives the keyboard back to the window.
    ASSERT_TRUE(QTest::qWaitFor([&] { return dialog.isNull(); }));
    window->activateWindow();
    EXPECT_EQ(view->moveGrid(), 0.25);
    EXPECT_EQ(QSettings().value("view/snapStep").toDouble(), 0.25);

    const Vec3 start = ball().center;
    const QPoint grab = selectBall();
    key(Qt::Key_G);
    movePointer(grab, grab + QPoint(61, 23), Qt::ControlModifier);
    click(grab + QPoint(61, 23));
    expectOnGrid(ball().center - start, 0.25);
    MainWindow again;
    EXPECT_EQ(again.renderView()->moveGrid(), 0.25);
}

TEST_F(ViewMoveTest, EscapeOrRightClick_PutTheBallBackBitForBit_AndLeaveNoStep) {
    const Scene before = doc->scene();
    const int steps = doc->undoStack()->count();
    const QPoint grab = selectBall();
    for (const bool escape : {true, false}) {
        key(Qt::Key_G);
        movePointer(grab, grab + QPoint(-50, 20));
        EXPECT_NE(ball().center, before.spheres[kBlueBall].center) << "it moved meanwhile";
        if (escape)
            key(Qt::Key_Escape);
        else
            click(grab + QPoint(-50, 20), {}, Qt::RightButton);
        EXPECT_FALSE(view->moving());
        EXPECT_EQ(doc->scene(), before);
        EXPECT_EQ(doc->undoStack()->count(), steps);
        EXPECT_FALSE(doc->undoStack()->canRedo());
        EXPECT_FALSE(doc->isModified());
        EXPECT_TRUE(window->statusBar()->currentMessage().isEmpty());
        QTest::mouseMove(shownWindow(), inWindow(grab));
    }
}

TEST_F(ViewMoveTest, KeysDuringAMove_AreTheMovesNotShortcuts) {
    const Camera camera = doc->scene().camera;
    selectBall();
    key(Qt::Key_G);
    key(Qt::Key_W);     // walk forward, outside a move
    key(Qt::Key_Home);  // reset the camera
    key(Qt::Key_Escape);
    EXPECT_EQ(doc->scene().camera, camera);
}

TEST_F(ViewMoveTest, ShiftD_ACopyFollowsThePointer_TheOriginalStays_OneUndoStep) {
    const Scene before = doc->scene();
    const int steps = doc->undoStack()->count();
    const QPoint grab = selectBall();
    key(Qt::Key_D, Qt::ShiftModifier);
    ASSERT_TRUE(view->moving());
    movePointer(grab, grab + QPoint(-70, 0));
    // The sphere page, on the copy, counts it among its material's users at
    // once, though it counts them over every sphere only when a gesture adds one.
    const auto* users = window->findChild<QLabel*>(QStringLiteral("sphereMaterialUsers"));
    ASSERT_NE(users, nullptr);
    EXPECT_EQ(users->text(), QStringLiteral("Shared by 2 spheres"));
    click(grab + QPoint(-70, 0));

    const Scene& s = doc->scene();
    ASSERT_EQ(s.spheres.size(), before.spheres.size() + 1);
    EXPECT_EQ(s.spheres[kBlueBall], before.spheres[kBlueBall]) << "the original stays";
    const Sphere& copy = s.spheres.back();
    EXPECT_EQ(copy.radius, ball().radius);
    EXPECT_EQ(copy.material, ball().material);
    EXPECT_LT(project(s, copy.center).x(), project(s, ball().center).x() - 5) << "moved left";
    EXPECT_EQ(doc->undoStack()->count(), steps + 1);
    EXPECT_EQ(doc->undoStack()->undoText(), QString("Duplicate and move blue ball"));
    EXPECT_EQ(users->text(), QStringLiteral("Shared by 2 spheres"));
    doc->undoStack()->undo();
    EXPECT_EQ(doc->scene(), before);
}

TEST_F(ViewMoveTest, ShiftD_ThenEscape_KeepsTheCopyOnTheOriginal) {
    const Scene before = doc->scene();
    const QPoint grab = selectBall();
    key(Qt::Key_D, Qt::ShiftModifier);
    movePointer(grab, grab + QPoint(40, 40));
    key(Qt::Key_Escape);
    ASSERT_EQ(doc->scene().spheres.size(), before.spheres.size() + 1);
    EXPECT_EQ(doc->scene().spheres.back().center, ball().center);
    doc->undoStack()->undo();
    EXPECT_EQ(doc->scene(), before);
}

// Shift+A with the pointer over the picture: a new sphere resting on what the
// pointer is on, moving with it at once; a click leaves it there.
TEST_F(ViewMoveTest, ShiftA_OnTheFloor_ANewSphereRestsOnIt_OnABall_TouchesIt) {
    const Scene before = doc->scene();
    const Sphere floor = before.spheres[kFloor];
    // A point of the floor in front of the balls, and the blue ball's centre.
    const QPoint onFloor = widgetPoint(project(before, Vec3(0.2, -0.5, 0.8)));
    const QPoint onBall = drawnCentre().toPoint();
    for (const QPoint at : {onFloor, onBall}) {
        const std::size_t count = doc->scene().spheres.size();
        QTest::mouseMove(shownWindow(), inWindow(at));
        key(Qt::Key_A, Qt::ShiftModifier);
        ASSERT_TRUE(view->moving());
        click(at);
        ASSERT_EQ(doc->scene().spheres.size(), count + 1);
        const Sphere& added = doc->scene().spheres.back();
        const Sphere& under = at == onFloor ? floor : before.spheres[kBlueBall];
        EXPECT_NEAR(glm::length(added.center - under.center), under.radius + added.radius,
                    1e-9 * (under.radius + added.radius))
            << "touching " << under.name;
        EXPECT_EQ(doc->undoStack()->undoText(), QString("Add sphere"));
        // One step takes it away again, before the next is added from the seed.
        doc->undoStack()->undo();
        EXPECT_EQ(doc->scene(), before);
    }
}

// The floor is a sphere whose centre lies 100,000 units below: moved in the
// plane through its centre, a pixel would be some fifty units. The point of
// the floor grabbed follows the pointer instead.
TEST_F(ViewMoveTest, G_OnTheFloor_ThePointGrabbedFollowsThePointer) {
    const Scene before = doc->scene();
    const Vec3 grabbed(0.2, -0.5, 0.8);  // on the floor, in front of the balls
    const QPoint at = widgetPoint(project(before, grabbed));
    QTest::mouseClick(shownWindow(), Qt::LeftButton, {}, inWindow(at));
    ASSERT_EQ(window->scenePanel()->currentIndex(), int(kFloor));
    QTest::mouseMove(shownWindow(), inWindow(at));
    key(Qt::Key_G);
    const QPoint by(40, 0);
    movePointer(at, at + by);
    click(at + by);
    const Vec3 moved = doc->scene().spheres[kFloor].center - before.spheres[kFloor].center;
    // Where the grabbed point is drawn now: the pointer's place.
    const QPoint drawnAt = widgetPoint(project(doc->scene(), grabbed + moved));
    EXPECT_NEAR(drawnAt.x(), (at + by).x(), 2) << glm::length(moved) << " units";
    EXPECT_NEAR(drawnAt.y(), (at + by).y(), 2);
    EXPECT_GT(glm::length(moved), 0.01);
}

TEST_F(ViewMoveTest, ALight_MovesAsASphereDoes) {
    window->scenePanel()->select(ItemKind::Light, 0);
    const Vec3 start = doc->scene().lights[0].position;
    key(Qt::Key_G);
    key(Qt::Key_Y);
    key(Qt::Key_3);
    key(Qt::Key_Enter);
    EXPECT_EQ(doc->scene().lights[0].position, start + Vec3(0, 3, 0));
    EXPECT_EQ(doc->undoStack()->undoText(), QString("Move key"));
}

}  // namespace
}  // namespace whitted::ui
