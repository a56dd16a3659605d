// The main() of the editor's GUI tests: a QApplication for the whole run,
// offscreen unless QT_QPA_PLATFORM says otherwise, and settings and app data
// in Qt's test locations under the test's own name, never the user's.
#pragma once

#include <QApplication>
#include <QSettings>
#include <QStandardPaths>

#include "support/qt_test_main.h"

namespace whitted::test {

// Runs every test of the executable; `clearSettings` starts from no saved
// window state or recent files.
inline int runGuiTests(int argc, char** argv, const char* name, bool clearSettings = true) {
    QStandardPaths::setTestModeEnabled(true);
    return runQtTests<QApplication>(argc, argv, [&] {
        // A test that closes its last window (Ctrl+Q) must not end the application
        // for the tests after it: a quitting application's dialogs never answered.
        QApplication::setQuitOnLastWindowClosed(false);
        QApplication::setOrganizationName("WhittedTests");
        QApplication::setApplicationName(QString::fromLatin1(name));
        if (clearSettings) QSettings().clear();
    });
}

}  // namespace whitted::test
