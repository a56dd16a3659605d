// The main() of the editor's GUI tests: one QApplication for the whole run,
// offscreen on a laptop's 1366 x 768 screen (support/laptop_screen.json)
// unless QT_QPA_PLATFORM names another platform, and each test's settings
// and app data in Qt's test locations under the test's own name, never the
// user's and never another test's (CTest runs two at a time).
#include <QApplication>
#include <QFile>
#include <QSettings>
#include <QStandardPaths>

#include <gtest/gtest.h>

#include "support/qt_test_main.h"

namespace {

// Each test starts with no saved settings (window state, recent files) and
// leaves no settings file behind; its app data (recovery copies) lies in a
// folder of its own name.
class SettingsOfTheTestsOwn : public ::testing::EmptyTestEventListener {
    void OnTestStart(const ::testing::TestInfo& test) override {
        QString name = QStringLiteral("%1.%2").arg(QString::fromLatin1(test.test_suite_name()),
                                                   QString::fromLatin1(test.name()));
        name.replace(QLatin1Char('/'), QLatin1Char('_'));
        QApplication::setApplicationName(name);
        QSettings().clear();
    }
    void OnTestEnd(const ::testing::TestInfo&) override {
        QSettings settings;
        settings.clear();
        settings.sync();
        QFile::remove(settings.fileName());
    }
};

}  // namespace

int main(int argc, char** argv) {
    const QByteArray platform = qgetenv("QT_QPA_PLATFORM");
    if (platform.isEmpty() || platform == "offscreen")
        qputenv("QT_QPA_PLATFORM", "offscreen:configfile=" WHITTED_TEST_SCREEN);
    QStandardPaths::setTestModeEnabled(true);
    return whitted::test::runQtTests<QApplication>(argc, argv, [] {
        // A test that closes its last window (Ctrl+Q) must not end the application
        // for the tests after it: a quitting application's dialogs never answered.
        QApplication::setQuitOnLastWindowClosed(false);
        QApplication::setOrganizationName("WhittedTests");
        ::testing::UnitTest::GetInstance()->listeners().Append(new SettingsOfTheTestsOwn);
    });
}
