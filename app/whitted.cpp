// whitted: the scene editor. Opens the scene given as its argument, or a new one.
#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>

#include "base/heap_reuse.h"
#include "editor/main_window.h"

int main(int argc, char** argv) {
    whitted::reuseHeapForLargeBlocks();
    QApplication app(argc, argv);
    QApplication::setOrganizationName("Whitted");
    QApplication::setApplicationName("whitted");
    QApplication::setApplicationDisplayName("Whitted");
    QApplication::setApplicationVersion(WHITTED_VERSION);
    // The desktop file's name (resources/): lets the desktop match the window to
    // its launcher and icon.
    QGuiApplication::setDesktopFileName("io.github.whitted.Whitted");
    QApplication::setWindowIcon(QIcon(":/icons/whitted.svg"));

    QCommandLineParser parser;
    parser.setApplicationDescription("Scene editor for a classic Whitted ray tracer.");
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument("scene", "Scene file to open (JSON, whitted-scene v1).");
    parser.process(app);

    whitted::ui::MainWindow window;
    window.show();
    if (!parser.positionalArguments().isEmpty())
        window.openFile(parser.positionalArguments().first());
    // After the scene is open, so that restoring puts the copy on top of it.
    window.offerRecovery();
    return app.exec();
}
