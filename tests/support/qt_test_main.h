// The main() of every test executable that needs a Qt application object (its
// own, so it links gtest rather than gtest_main): one application for the whole
// run, offscreen unless QT_QPA_PLATFORM says otherwise. Free of Qt Widgets, so
// that tests linking only Qt Core can use it too.
#pragma once

#include <QCoreApplication>

#include <functional>
#include <type_traits>

#include <gtest/gtest.h>

namespace whitted::test {

// Runs every test of the executable under an application of type App
// (QCoreApplication, QGuiApplication or QApplication); `setUp` runs once the
// application exists, before the first test.
template <class App>
int runQtTests(int argc, char** argv, const std::function<void()>& setUp = {}) {
    if constexpr (!std::is_same_v<App, QCoreApplication>)
        if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    App app(argc, argv);
    if (setUp) setUp();
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}

}  // namespace whitted::test
