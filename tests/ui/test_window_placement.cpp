// Where the editor's window opens: on a first start it fits the screen it
// opens on (the tests' screen is a laptop's 1366 x 768, smaller than the
// 1400 x 860 the window takes on a large one); later where the user left it,
// but only if a screen can show it there.
#include <gtest/gtest.h>

#include <QScreen>
#include <QSettings>
#include <QStatusBar>
#include <QTest>

#include <memory>

#include "editor/main_window.h"
#include "editor/window_placement.h"

namespace whitted::ui {
namespace {

QRect availableArea() {
    return QGuiApplication::primaryScreen()->availableGeometry();
}

// A new window, shown, with its settings as the last one closed left them.
std::unique_ptr<MainWindow> openWindow() {
    auto window = std::make_unique<MainWindow>();
    window->show();
    if (!QTest::qWaitForWindowExposed(window.get())) ADD_FAILURE() << "never exposed";
    return window;
}

TEST(WindowPlacement, FirstStart_SmallScreen_TheWholeWindowIsOnIt) {
    const QRect available = availableArea();
    if (available.width() >= 1400 || available.height() >= 860)
        GTEST_SKIP() << "needs a screen smaller than 1400 x 860, as the tests' offscreen one";
    const auto window = openWindow();
    EXPECT_EQ(window->size(), QSize(available.size() * 0.9));
    EXPECT_TRUE(available.contains(window->geometry())) << "centred, all of it on the screen";
    const QRect statusBar(window->statusBar()->mapTo(window.get(), QPoint(0, 0)),
                          window->statusBar()->size());
    EXPECT_TRUE(window->rect().contains(statusBar)) << "the status bar is inside the window";
}

TEST(WindowPlacement, FirstWindowSize_LargeScreenGetsItsOwnSize_SmallOneNineTenths) {
    EXPECT_EQ(firstWindowSize({2560, 1400}), QSize(1400, 860));
    EXPECT_EQ(firstWindowSize({1366, 740}), QSize(1229, 666));
}

TEST(WindowPlacement, Reopened_WhereTheUserLeftIt) {
    const QRect left(40, 30, 1100, 600);
    {
        const auto window = openWindow();
        window->setGeometry(left);
        QTest::qWait(10);
        window->close();
    }
    const auto window = openWindow();
    EXPECT_EQ(window->geometry(), left);
}

TEST(WindowPlacement, RememberedOnALargerScreen_OpensAsOnAFirstStart) {
    {
        const auto window = openWindow();
        window->setGeometry(QRect(QPoint(1800, 900), QSize(1400, 860)));
        QTest::qWait(10);
        window->close();
    }
    ASSERT_TRUE(QSettings().contains("window/geometry"));
    const auto window = openWindow();
    const QRect available = availableArea();
    EXPECT_EQ(window->size(), QSize(available.size() * 0.9));
    EXPECT_TRUE(available.contains(window->geometry()));
}

}  // namespace
}  // namespace whitted::ui
