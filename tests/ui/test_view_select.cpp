// Selecting many spheres and working on them all at once, driven as a user
// drives it: mouse and key events sent to the shown window, never to the view
// directly. Click and Shift+click in the picture and the list, A / Alt+A /
// Ctrl+I, the box (B), Same Material (Shift+L); then G, S, Delete, Shift+D,
// Alt+drag and the property panel on the whole selection, each one undo step
// that puts everything back; and fly mode's keys kept apart from A, S and G.
#include <QComboBox>
#include <QItemSelectionModel>
#include <QListView>
#include <QStatusBar>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "panels/number_field.h"
#include "panels/scene_panel.h"
#include "viewport/view_overlay.h"

#include "support/window_events.h"

namespace whitted::ui {
namespace {

class ViewSelectTest : public WindowEventsTest {
  protected:
    const Sphere& sphere(int index) const { return doc->scene().spheres[index]; }
    QPointF drawnCentre(int index) const { return drawn(sphere(index).center); }
    QPoint centreOf(int index) const { return drawnCentre(index).toPoint(); }
    // The spheres whose centres are drawn inside `box` (widget coordinates).
    std::vector<int> centresInside(const QRectF& box) const {
        const Scene& s = doc->scene();
        std::vector<int> inside;
        for (int i = 0; i < int(s.spheres.size()); ++i)
            if (projectToImage(s.camera, kWidth, kHeight, s.spheres[i].center) &&
                box.contains(drawnCentre(i)))
                inside.push_back(i);
        return inside;
    }

    // Clicks (Shift: Shift+clicks) a sphere's drawn centre; the pointer stays there.
    void clickSphere(int index, Qt::KeyboardModifiers modifiers = {}) {
        const QPoint at = centreOf(index);
        click(at, modifiers);
        QTest::mouseMove(shownWindow(), inWindow(at));
    }
    // Blue clicked, purple Shift+clicked; the pointer on the purple ball.
    void selectBlueAndPurple() {
        clickSphere(kBlueBall);
        clickSphere(kPurpleBall, Qt::ShiftModifier);
        ASSERT_EQ(selected(), (std::vector<int>{kBlueBall, kPurpleBall}));
    }

    const std::vector<int>& selected() const { return doc->selection()->indices(); }
    std::vector<std::string> selectedNames() const {
        std::vector<std::string> names;
        for (int i : selected()) names.push_back(sphere(i).name);
        return names;
    }
    // The rows the sphere list shows selected.
    std::vector<int> listRows() const {
        std::vector<int> rows;
        for (const QModelIndex& i : list()->selectionModel()->selectedRows())
            rows.push_back(i.row());
        std::sort(rows.begin(), rows.end());
        return rows;
    }
    QListView* list() const { return child<QListView>("sphereList"); }
    int steps() { return doc->undoStack()->count(); }
    QString stepName() { return doc->undoStack()->undoText(); }
};

TEST_F(ViewSelectTest, ShiftClick_AddsABallAndTakesItOut_TheListShowsBoth) {
    clickSphere(kBlueBall);
    EXPECT_EQ(selected(), (std::vector<int>{kBlueBall}));
    clickSphere(kPurpleBall, Qt::ShiftModifier);
    EXPECT_EQ(doc->selection()->kind(), ItemKind::Sphere);
    EXPECT_EQ(selected(), (std::vector<int>{kBlueBall, kPurpleBall}));
    EXPECT_EQ(doc->selection()->active(), int(kPurpleBall)) << "the last clicked";
    ASSERT_NE(list(), nullptr);
    EXPECT_EQ(listRows(), (std::vector<int>{kBlueBall, kPurpleBall}));

    clickSphere(kBlueBall, Qt::ShiftModifier);
    EXPECT_EQ(selected(), (std::vector<int>{kPurpleBall}));
    EXPECT_EQ(doc->selection()->active(), int(kPurpleBall));
    EXPECT_EQ(listRows(), (std::vector<int>{kPurpleBall}));
}

TEST_F(ViewSelectTest, ShiftClickInTheList_SelectsTheRange) {
    QListView* spheres = list();
    ASSERT_NE(spheres, nullptr);
    auto rowCentre = [&](int row) {
        return spheres->visualRect(spheres->model()->index(row, 0)).center();
    };
    QTest::mouseClick(spheres->viewport(), Qt::LeftButton, {}, rowCentre(0));
    EXPECT_EQ(selected(), (std::vector<int>{0}));
    QTest::mouseClick(spheres->viewport(), Qt::LeftButton, Qt::ShiftModifier, rowCentre(2));
    EXPECT_EQ(doc->selection()->kind(), ItemKind::Sphere);
    EXPECT_EQ(selected(), (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(doc->selection()->active(), 2);
}

TEST_F(ViewSelectTest, A_SelectsAll_AltA_None_CtrlI_Inverts) {
    clickSphere(kBlueBall);
    ASSERT_TRUE(view->hasFocus());
    key(Qt::Key_A);
    EXPECT_EQ(doc->selection()->count(), 4);
    EXPECT_EQ(selected(), (std::vector<int>{0, 1, 2, 3}));
    key(Qt::Key_A, Qt::AltModifier);
    EXPECT_TRUE(doc->selection()->empty());
    EXPECT_EQ(doc->selection()->active(), -1);

    clickSphere(kBlueBall);
    ASSERT_EQ(selected(), (std::vector<int>{kBlueBall}));
    key(Qt::Key_I, Qt::ControlModifier);
    EXPECT_EQ(doc->selection()->kind(), ItemKind::Sphere);
    EXPECT_EQ(selected(), (std::vector<int>{kPurpleBall, kWhiteBall, kFloor}));
}

TEST_F(ViewSelectTest, B_ThenDrag_SelectsTheBallsInTheBox_ShiftAdds_EscapeCancels) {
    clickSphere(kWhiteBall);
    ASSERT_EQ(selected(), (std::vector<int>{kWhiteBall}));
    // A box round the blue and purple balls' centres, its top half way to the
    // white ball's centre (drawn just above them, between them).
    const QPointF blue = drawnCentre(kBlueBall), purple = drawnCentre(kPurpleBall);
    const QPointF white = drawnCentre(kWhiteBall);
    const double top = std::min(blue.y(), purple.y());
    const QRectF box(
        QPointF(std::min(blue.x(), purple.x()) - 15,
                white.y() < top ? (white.y() + top) / 2 : top - 15),
        QPointF(std::max(blue.x(), purple.x()) + 15, std::max(blue.y(), purple.y()) + 15));
    ASSERT_EQ(centresInside(box), (std::vector<int>{kBlueBall, kPurpleBall}))
        << "white at (" << white.x() << ", " << white.y() << ")";
    const QPoint from = box.topLeft().toPoint() + QPoint(1, 1);
    const QPoint to = box.bottomRight().toPoint() - QPoint(1, 1);
    const Camera camera = doc->scene().camera;
    const int n = steps();

    key(Qt::Key_B);
    EXPECT_FALSE(window->statusBar()->currentMessage().isEmpty()) << "it says what B waits for";
    drag(from, to);
    EXPECT_EQ(doc->selection()->kind(), ItemKind::Sphere);
    EXPECT_EQ(selected(), (std::vector<int>{kBlueBall, kPurpleBall}));
    EXPECT_EQ(doc->scene().camera, camera) << "the drag drew a box, it did not orbit";
    EXPECT_EQ(steps(), n);

    // Shift: the white ball is added to the two.
    const QRectF round(white - QPointF(8, 8), white + QPointF(8, 8));
    ASSERT_EQ(centresInside(round), (std::vector<int>{kWhiteBall}));
    key(Qt::Key_B);
    drag(round.topLeft().toPoint(), round.bottomRight().toPoint(), Qt::ShiftModifier);
    EXPECT_EQ(selected(), (std::vector<int>{kBlueBall, kPurpleBall, kWhiteBall}));

    // Escape after B: no box; the next drag orbits and the selection stays.
    key(Qt::Key_B);
    key(Qt::Key_Escape);
    EXPECT_TRUE(window->statusBar()->currentMessage().isEmpty());
    drag(from, to);
    EXPECT_EQ(selected(), (std::vector<int>{kBlueBall, kPurpleBall, kWhiteBall}));
    EXPECT_NE(doc->scene().camera, camera) << "without the box, a left drag orbits";
}

TEST_F(ViewSelectTest, ShiftL_SelectsEverySphereOfTheSameMaterial) {
    // The white ball made blue too, so that the blue ball has a fellow.
    ASSERT_TRUE(editAndWait([](Scene& s) { s.spheres[kWhiteBall].material = "blue"; }));
    clickSphere(kBlueBall);
    ASSERT_EQ(selected(), (std::vector<int>{kBlueBall}));
    key(Qt::Key_L, Qt::ShiftModifier);

    std::vector<int> expected;
    const Scene& s = doc->scene();
    for (int i = 0; i < int(s.spheres.size()); ++i)
        if (s.spheres[i].material == s.spheres[kBlueBall].material) expected.push_back(i);
    ASSERT_EQ(expected, (std::vector<int>{kBlueBall, kWhiteBall}));
    EXPECT_EQ(doc->selection()->kind(), ItemKind::Sphere);
    EXPECT_EQ(selected(), expected);
    EXPECT_EQ(doc->selection()->active(), int(kBlueBall));
}

// Past kMostOutlines selected spheres each shows a dot at its centre, drawn
// over the picture whether or not the ball is hidden; Alt+A takes them away.
TEST_F(ViewSelectTest, A_OnMoreBallsThanAreOutlined_ADotAtEachCentre_AltATakesThemAway) {
    const int balls = kMostOutlines + 100;
    ASSERT_TRUE(editAndWait([&](Scene& s) {
        // A grid of small balls in front of the seed's balls, 2 cm apart.
        for (int i = 0; i < balls; ++i)
            s.spheres.push_back({"dot " + std::to_string(i),
                                 {-0.6 + 0.02 * (i % 60), 0.2 + 0.02 * (i / 60), 3.0}, 0.005,
                                 "white"});
    }));
    clickSphere(kBlueBall);
    key(Qt::Key_A);
    ASSERT_EQ(doc->selection()->count(), balls + 4);
    const QColor dot(215, 95, 15);  // the others of a selection (view_overlay.cpp)
    auto colourAt = [&](int index) {
        const QImage shown = view->grab().toImage();
        const QPointF at = drawnCentre(index);
        EXPECT_TRUE(view->imageRect().contains(at.toPoint()));
        return shown.pixelColor(int(std::floor(at.x())), int(std::floor(at.y())));
    };
    const int count = int(doc->scene().spheres.size());
    for (int index : {4, 4 + balls / 2, count - 1, int(kPurpleBall)}) {
        SCOPED_TRACE("sphere " + std::to_string(index));
        EXPECT_EQ(colourAt(index), dot);
    }
    key(Qt::Key_A, Qt::AltModifier);
    EXPECT_NE(colourAt(4 + balls / 2), dot);
}

TEST_F(ViewSelectTest, G_WithTwoSelected_BothMoveByTheSameOffset_OneStep_TypedMovesBothExactly) {
    const Scene before = doc->scene();
    selectBlueAndPurple();
    const QPoint grab = centreOf(kPurpleBall);
    const int n = steps();

    key(Qt::Key_G);
    EXPECT_TRUE(view->moving());
    movePointer(grab, grab + QPoint(60, 0));
    click(grab + QPoint(60, 0));
    EXPECT_FALSE(view->moving());

    const Vec3 blueBy = sphere(kBlueBall).center - before.spheres[kBlueBall].center;
    const Vec3 purpleBy = sphere(kPurpleBall).center - before.spheres[kPurpleBall].center;
    EXPECT_GT(glm::length(purpleBy), 0.1);
    for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(blueBy[axis], purpleBy[axis], 1e-12) << axis;
    EXPECT_NEAR(drawnCentre(kPurpleBall).x() - drawn(before.spheres[kPurpleBall].center).x(), 60, 2)
        << "the grabbed ball followed the pointer";
    EXPECT_EQ(sphere(kWhiteBall), before.spheres[kWhiteBall]);
    EXPECT_EQ(steps(), n + 1);
    EXPECT_EQ(stepName(), QString("Move 2 spheres"));
    // Ten pointer events, one before and after kept: a move of many spheres
    // must not keep a copy of them for every event.
    EXPECT_EQ(doc->undoStack()->command(doc->undoStack()->index() - 1)->childCount(), 1);
    doc->undoStack()->undo();
    EXPECT_EQ(doc->scene(), before);

    key(Qt::Key_G);
    key(Qt::Key_X);
    key(Qt::Key_2);
    key(Qt::Key_Return);
    EXPECT_EQ(sphere(kBlueBall).center, before.spheres[kBlueBall].center + Vec3(2, 0, 0));
    EXPECT_EQ(sphere(kPurpleBall).center, before.spheres[kPurpleBall].center + Vec3(2, 0, 0));
    EXPECT_EQ(steps(), n + 1);
    EXPECT_EQ(stepName(), QString("Move 2 spheres"));
}

TEST_F(ViewSelectTest, EscapeDuringAMoveOfTwo_PutsBothBackBitForBit_NoStep) {
    selectBlueAndPurple();
    const Scene before = doc->scene();
    const int n = steps();
    const QPoint grab = centreOf(kPurpleBall);
    key(Qt::Key_G);
    movePointer(grab, grab + QPoint(-40, 30));
    EXPECT_NE(sphere(kBlueBall).center, before.spheres[kBlueBall].center) << "it moved meanwhile";
    EXPECT_NE(sphere(kPurpleBall).center, before.spheres[kPurpleBall].center);
    key(Qt::Key_Escape);
    EXPECT_FALSE(view->moving());
    EXPECT_EQ(doc->scene(), before);
    EXPECT_EQ(steps(), n);
    EXPECT_FALSE(doc->undoStack()->canRedo());
    EXPECT_FALSE(doc->isModified());
}

TEST_F(ViewSelectTest, S_ScalesTheRadiusByThePointersDistance_Typed3_Escape) {
    clickSphere(kBlueBall);
    const QPointF centre = drawnCentre(kBlueBall);
    const QPoint near = (centre + QPointF(40, 0)).toPoint();
    const QPoint far = (centre + QPointF(80, 0)).toPoint();
    QTest::mouseMove(shownWindow(), inWindow(near));
    const double r0 = sphere(kBlueBall).radius;
    const Vec3 start = sphere(kBlueBall).center;
    const int n = steps();

    key(Qt::Key_S);
    EXPECT_TRUE(view->moving());
    movePointer(near, far);
    click(far);
    EXPECT_FALSE(view->moving());
    EXPECT_NEAR(sphere(kBlueBall).radius / r0, 2.0, 0.1) << "twice as far from the centre";
    EXPECT_EQ(sphere(kBlueBall).center, start) << "scaled about its centre";
    EXPECT_EQ(steps(), n + 1);
    EXPECT_EQ(stepName(), QString("Scale blue ball"));

    const double r1 = sphere(kBlueBall).radius;
    key(Qt::Key_S);
    key(Qt::Key_3);
    key(Qt::Key_Return);
    EXPECT_EQ(sphere(kBlueBall).radius, r1 * 3);
    EXPECT_EQ(steps(), n + 2);

    const Scene before = doc->scene();
    key(Qt::Key_S);
    movePointer(far, near);
    EXPECT_NE(sphere(kBlueBall).radius, before.spheres[kBlueBall].radius) << "it shrank meanwhile";
    key(Qt::Key_Escape);
    EXPECT_FALSE(view->moving());
    EXPECT_EQ(doc->scene(), before);
    EXPECT_EQ(sphere(kBlueBall).radius, before.spheres[kBlueBall].radius);
    EXPECT_EQ(steps(), n + 2);
}

TEST_F(ViewSelectTest, S_WithTwoSelected_ScalesBothRadiiByTheSameFactor_OneStep) {
    const Scene before = doc->scene();
    selectBlueAndPurple();
    // The pointer starts on the purple ball and goes half as far again from
    // the two balls' middle.
    const QPointF middle =
        drawn((before.spheres[kBlueBall].center + before.spheres[kPurpleBall].center) / 2.0);
    const QPoint grab = centreOf(kPurpleBall);
    const QPoint out = (middle + (QPointF(grab) - middle) * 1.5).toPoint();
    const int n = steps();

    key(Qt::Key_S);
    EXPECT_TRUE(view->moving());
    movePointer(grab, out);
    click(out);
    const double blueFactor = sphere(kBlueBall).radius / before.spheres[kBlueBall].radius;
    const double purpleFactor = sphere(kPurpleBall).radius / before.spheres[kPurpleBall].radius;
    EXPECT_NEAR(purpleFactor, 1.5, 0.075);
    EXPECT_NEAR(blueFactor, purpleFactor, 1e-12);
    EXPECT_EQ(sphere(kWhiteBall), before.spheres[kWhiteBall]);
    EXPECT_EQ(steps(), n + 1);
    EXPECT_EQ(stepName(), QString("Scale 2 spheres"));
    doc->undoStack()->undo();
    EXPECT_EQ(doc->scene(), before);
}

TEST_F(ViewSelectTest, Delete_WithTwoSelected_RemovesBoth_UndoBringsThemBackSelected) {
    selectBlueAndPurple();
    const Scene before = doc->scene();
    const int n = steps();
    key(Qt::Key_Delete);
    const Scene& s = doc->scene();
    ASSERT_EQ(s.spheres.size(), before.spheres.size() - 2);
    for (const Sphere& sp : s.spheres) {
        EXPECT_NE(sp.name, "blue ball");
        EXPECT_NE(sp.name, "purple ball");
    }
    EXPECT_EQ(steps(), n + 1);

    doc->undoStack()->undo();
    EXPECT_EQ(doc->scene(), before);
    EXPECT_EQ(selectedNames(), (std::vector<std::string>{"blue ball", "purple ball"}));
    EXPECT_EQ(selected(), (std::vector<int>{kBlueBall, kPurpleBall}));
}

TEST_F(ViewSelectTest, ShiftD_WithTwoSelected_TwoCopiesFollowThePointer_OneStep) {
    const Scene before = doc->scene();
    selectBlueAndPurple();
    const QPoint grab = centreOf(kPurpleBall);
    const int n = steps();
    key(Qt::Key_D, Qt::ShiftModifier);
    ASSERT_TRUE(view->moving());
    movePointer(grab, grab + QPoint(40, 25));
    click(grab + QPoint(40, 25));
    EXPECT_FALSE(view->moving());

    const Scene& s = doc->scene();
    ASSERT_EQ(s.spheres.size(), before.spheres.size() + 2);
    for (std::size_t i = 0; i < before.spheres.size(); ++i)
        EXPECT_EQ(s.spheres[i], before.spheres[i]) << "the originals stay: " << i;
    const Sphere& blueCopy = s.spheres[before.spheres.size()];
    const Sphere& purpleCopy = s.spheres[before.spheres.size() + 1];
    EXPECT_EQ(blueCopy.radius, before.spheres[kBlueBall].radius);
    EXPECT_EQ(blueCopy.material, before.spheres[kBlueBall].material);
    EXPECT_EQ(purpleCopy.radius, before.spheres[kPurpleBall].radius);
    EXPECT_EQ(purpleCopy.material, before.spheres[kPurpleBall].material);
    const Vec3 blueBy = blueCopy.center - before.spheres[kBlueBall].center;
    const Vec3 purpleBy = purpleCopy.center - before.spheres[kPurpleBall].center;
    EXPECT_GT(glm::length(purpleBy), 0.1) << "the copies moved with the pointer";
    for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(blueBy[axis], purpleBy[axis], 1e-12) << axis;
    EXPECT_EQ(selected(),
              (std::vector<int>{int(before.spheres.size()), int(before.spheres.size()) + 1}))
        << "the copies are selected";
    EXPECT_EQ(steps(), n + 1);
    EXPECT_EQ(stepName(), QString("Duplicate and move 2 spheres"));
    doc->undoStack()->undo();
    EXPECT_EQ(doc->scene(), before);
}

TEST_F(ViewSelectTest, PropertyPanel_TwoSelected_MixedRadius_TypedValueAndMaterialGoToBoth) {
    ASSERT_TRUE(editAndWait([](Scene& s) { s.spheres[kPurpleBall].radius = 0.45; }));
    selectBlueAndPurple();
    ASSERT_NE(sphere(kBlueBall).radius, sphere(kPurpleBall).radius);
    auto* radius = child<NumberSpinBox>("sphereRadius");
    ASSERT_NE(radius, nullptr);
    EXPECT_TRUE(radius->mixed());

    int n = steps();
    radius->setFocus();
    radius->selectAll();
    QTest::keyClicks(radius, QStringLiteral("0.3"));
    QTest::keyClick(radius, Qt::Key_Return);
    EXPECT_EQ(sphere(kBlueBall).radius, 0.3);
    EXPECT_EQ(sphere(kPurpleBall).radius, 0.3);
    EXPECT_EQ(steps(), n + 1);
    EXPECT_FALSE(radius->mixed());
    EXPECT_EQ(radius->value(), 0.3);

    // The white material, picked from the combo box's list.
    auto* material = child<QComboBox>("sphereMaterial");
    ASSERT_NE(material, nullptr);
    const int white = material->findText(QStringLiteral("white"));
    ASSERT_GE(white, 0);
    n = steps();
    material->showPopup();
    QAbstractItemView* popup = material->view();
    ASSERT_TRUE(QTest::qWaitFor([&] { return popup->isVisible(); }));
    const QPoint item = popup->visualRect(popup->model()->index(white, 0)).center();
    QTest::mouseClick(popup->viewport(), Qt::LeftButton, {}, item);
    EXPECT_TRUE(QTest::qWaitFor([&] { return !popup->isVisible(); }));
    EXPECT_EQ(sphere(kBlueBall).material, "white");
    EXPECT_EQ(sphere(kPurpleBall).material, "white");
    EXPECT_EQ(steps(), n + 1);
}

// Two spheres of two materials: the sphere page's finish rows show "mixed"
// where the materials differ, and a value typed there goes to both materials.
TEST_F(ViewSelectTest, PropertyPanel_TwoMaterials_FinishTypedOnceSetsBoth) {
    const int blue = findMaterial(doc->scene(), sphere(kBlueBall).material);
    const int purple = findMaterial(doc->scene(), sphere(kPurpleBall).material);
    ASSERT_NE(blue, purple);
    ASSERT_TRUE(editAndWait([&](Scene& s) { s.materials[purple].reflectivity = 0.1; }));
    selectBlueAndPurple();
    auto* reflectivity = child<NumberSpinBox>("sphereMaterialReflectivity");
    ASSERT_NE(reflectivity, nullptr);
    ASSERT_NE(doc->scene().materials[blue].reflectivity, 0.1);
    EXPECT_TRUE(reflectivity->mixed());

    const int n = steps();
    reflectivity->setFocus();
    reflectivity->selectAll();
    QTest::keyClicks(reflectivity, QStringLiteral("0.7"));
    QTest::keyClick(reflectivity, Qt::Key_Return);
    EXPECT_EQ(doc->scene().materials[blue].reflectivity, 0.7);
    EXPECT_EQ(doc->scene().materials[purple].reflectivity, 0.7);
    EXPECT_EQ(steps(), n + 1);
    EXPECT_FALSE(reflectivity->mixed());
}

TEST_F(ViewSelectTest, AltDrag_OnASelectedBall_MovesIt_OneStep_CameraStays) {
    clickSphere(kBlueBall);
    const Camera camera = doc->scene().camera;
    const Vec3 start = sphere(kBlueBall).center;
    const QPointF drawnBefore = drawnCentre(kBlueBall);
    const QPoint at = centreOf(kBlueBall);
    const int n = steps();

    QTest::mousePress(shownWindow(), Qt::LeftButton, Qt::AltModifier, inWindow(at));
    EXPECT_TRUE(view->moving());
    movePointer(at, at + QPoint(50, 0), Qt::AltModifier);
    QTest::mouseRelease(shownWindow(), Qt::LeftButton, Qt::AltModifier,
                        inWindow(at + QPoint(50, 0)));
    EXPECT_FALSE(view->moving()) << "kept on release";

    EXPECT_NE(sphere(kBlueBall).center, start);
    EXPECT_NEAR(drawnCentre(kBlueBall).x() - drawnBefore.x(), 50, 2);
    EXPECT_NEAR(drawnCentre(kBlueBall).y() - drawnBefore.y(), 0, 2);
    EXPECT_EQ(doc->scene().camera, camera) << "no orbit";
    EXPECT_EQ(steps(), n + 1);
    EXPECT_EQ(stepName(), QString("Move blue ball"));
}

TEST_F(ViewSelectTest, ShiftWhileMoving_TheBallRestsOnTheFloor) {
    clickSphere(kBlueBall);
    const QPoint grab = centreOf(kBlueBall);
    const QPoint onFloor = drawn(Vec3(0.2, -0.5, 0.8)).toPoint();
    key(Qt::Key_G);
    movePointer(grab, onFloor, Qt::ShiftModifier);
    key(Qt::Key_Return);
    EXPECT_FALSE(view->moving());
    const Sphere& floor = sphere(kFloor);
    const Sphere& ball = sphere(kBlueBall);
    EXPECT_NEAR(glm::length(ball.center - floor.center), floor.radius + ball.radius,
                1e-9 * (floor.radius + ball.radius));
    EXPECT_LT(ball.center.z, 2.0) << "it came forward to where the pointer is";
    EXPECT_EQ(stepName(), QString("Move blue ball"));
}

TEST_F(ViewSelectTest, FlyKeys_OutsideFlyMode_AreSelectAndScale_InFlyMode_WMovesForward) {
    clickSphere(kBlueBall);
    const Scene before = doc->scene();
    const Camera camera = before.camera;

    key(Qt::Key_W);
    EXPECT_EQ(doc->scene().camera, camera) << "W walks only in fly mode";
    key(Qt::Key_A);
    EXPECT_EQ(doc->scene().camera, camera);
    EXPECT_EQ(selected(), (std::vector<int>{0, 1, 2, 3})) << "A selects all";
    key(Qt::Key_S);
    EXPECT_TRUE(view->moving()) << "S scales";
    key(Qt::Key_Escape);
    EXPECT_FALSE(view->moving());
    EXPECT_EQ(doc->scene(), before);
    EXPECT_EQ(selected(), (std::vector<int>{0, 1, 2, 3}));
    EXPECT_FALSE(view->flying());

    key(Qt::Key_AsciiTilde, Qt::ShiftModifier);
    ASSERT_TRUE(view->flying());
    key(Qt::Key_W);
    const Camera& now = doc->scene().camera;
    const Vec3 moved = now.position - camera.position;
    const Vec3 forward = camera.lookAt - camera.position;
    EXPECT_GT(glm::length(moved), 0.0);
    EXPECT_LT(glm::length(now.position - camera.lookAt), glm::length(forward))
        << "nearer to look_at";
    EXPECT_NEAR(glm::length(glm::cross(moved, forward)), 0, 1e-12 * glm::length(forward))
        << "straight ahead";
    EXPECT_EQ(selected(), (std::vector<int>{0, 1, 2, 3}));
    key(Qt::Key_Escape);
    EXPECT_FALSE(view->flying());
}

}  // namespace
}  // namespace whitted::ui
