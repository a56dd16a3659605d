// Events sent to the editor's shown window, as a user makes them: keys, clicks,
// drags and pointer moves at points of the render view. The GUI tests that
// drive gestures in the view share these (test_view_move.cpp,
// test_view_select.cpp), so that every one of them sends the same events.
#pragma once

#include "support/main_window_fixture.h"

namespace whitted::ui {

class WindowEventsTest : public MainWindowTest {
  protected:
    QWindow* shownWindow() const { return window->windowHandle(); }
    // A view point in the window's coordinates, where QTest's events on the window go.
    QPoint inWindow(QPoint viewPoint) const { return view->mapTo(window.get(), viewPoint); }
    // Where scene point `p` is drawn in the view, in continuous widget coordinates.
    QPointF drawn(const Vec3& p) const {
        const QRect r = view->imageRect();
        const QPointF image = project(doc->scene(), p);
        return QPointF(r.left() + image.x() * r.width() / kWidth,
                       r.top() + image.y() * r.height() / kHeight);
    }

    void key(Qt::Key k, Qt::KeyboardModifiers modifiers = {}) {
        QTest::keyClick(shownWindow(), k, modifiers);
    }
    // The pointer moved to `to` in ten steps, as a hand moves it.
    void movePointer(QPoint from, QPoint to, Qt::KeyboardModifiers modifiers = {}) {
        for (int i = 1; i <= 10; ++i)
            QTest::mouseEvent(QTest::MouseMove, shownWindow(), Qt::NoButton, modifiers,
                              inWindow(from + (to - from) * i / 10));
    }
    void click(QPoint at, Qt::KeyboardModifiers modifiers = {},
               Qt::MouseButton button = Qt::LeftButton) {
        QTest::mouseClick(shownWindow(), button, modifiers, inWindow(at));
    }
    // A left drag: pressed at `from`, moved there in ten steps with the button held, released.
    void drag(QPoint from, QPoint to, Qt::KeyboardModifiers modifiers = {}) {
        QTest::mousePress(shownWindow(), Qt::LeftButton, modifiers, inWindow(from));
        movePointer(from, to, modifiers);
        QTest::mouseRelease(shownWindow(), Qt::LeftButton, modifiers, inWindow(to));
    }
    // Each component of a move a whole number of grid steps.
    static void expectOnGrid(const Vec3& offset, double step) {
        EXPECT_NE(offset, Vec3(0.0));
        for (int axis = 0; axis < 3; ++axis) {
            const double steps = offset[axis] / step;
            EXPECT_NEAR(steps, std::round(steps), 1e-9) << axis;
        }
    }
};

}  // namespace whitted::ui
