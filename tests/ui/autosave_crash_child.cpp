// The editor that test_autosave kills: the real MainWindow opens the scene
// given as argv[1], makes one edit (the first sphere's radius becomes argv[2]),
// and prints "ready" once the recovery copy is on disk. Then it waits to be
// killed with SIGKILL, which no handler can see: whatever survives is what
// the next start finds. The recovery directory comes from WHITTED_RECOVERY_DIR.
#include <QApplication>

#include <cstdio>

#include "document/autosave.h"
#include "editor/main_window.h"

int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    if (argc < 3) return 2;
    whitted::ui::MainWindow window;
    window.show();
    if (!window.openFile(QString::fromLocal8Bit(argv[1]))) return 3;
    window.autosave()->setDelay(50);
    QObject::connect(window.autosave(), &whitted::ui::Autosave::written, [](const QString& error) {
        std::printf("%s\n", error.isEmpty() ? "ready" : "failed");
        std::fflush(stdout);
    });
    const double radius = std::atof(argv[2]);
    window.document()->edit("crash test edit",
                            [radius](whitted::Scene& s) { s.spheres[0].radius = radius; });
    return app.exec();
}
