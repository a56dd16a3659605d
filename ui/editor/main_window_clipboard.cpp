// MainWindow's Copy and Paste: the selected spheres (with their materials) or
// lights as a scene-file fragment on the system clipboard, pasted whole or
// not at all.
#include <QClipboard>
#include <QGuiApplication>
#include <QStatusBar>

#include "editor/main_window.h"
#include "scene/scene_fragment.h"
#include "scene/scene_io.h"

namespace whitted::ui {

namespace {

std::vector<std::size_t> sizes(const std::vector<int>& indices) {
    return {indices.begin(), indices.end()};
}

}  // namespace

void MainWindow::copySelection() {
    const SceneSelection& selection = *doc_.selection();
    if (selection.empty() || selection.kind() == ItemKind::Material) {
        statusBar()->showMessage(tr("Select spheres or lights to copy"), 5000);
        return;
    }
    const bool spheres = selection.kind() == ItemKind::Sphere;
    const std::string text = fragmentToJson(
        doc_.scene(), spheres ? sizes(selection.indices()) : std::vector<std::size_t>{},
        spheres ? std::vector<std::size_t>{} : sizes(selection.indices()));
    QGuiApplication::clipboard()->setText(QString::fromStdString(text));
    statusBar()->showMessage(tr("Copied %1").arg(countedNoun(selection.count(), selection.kind())),
                             5000);
}

void MainWindow::pasteClipboard() {
    const QString text = QGuiApplication::clipboard()->text();
    PasteResult pasted;
    try {
        pasted = pasteFragment(doc_.scene(), text.toStdString());
    } catch (const SceneError& e) {
        showError(tr("Cannot paste"),
                  tr("The clipboard does not hold spheres or lights copied from Whitted, so "
                     "nothing was pasted.\n\n%1")
                      .arg(QString::fromStdString(e.what())));
        return;
    }
    const std::size_t items = pasted.newSpheres.size() + pasted.newLights.size();
    QString error;
    if (!doc_.edit(
            items == 1 ? tr("Paste 1 item") : tr("Paste %1 items").arg(items),
            [&](Scene& s) { s = pasted.scene; }, &error)) {
        showError(tr("Cannot paste"), error);
        return;
    }
    const bool spheres = !pasted.newSpheres.empty();
    const auto& added = spheres ? pasted.newSpheres : pasted.newLights;
    doc_.selection()->set(spheres ? ItemKind::Sphere : ItemKind::Light,
                          std::vector<int>(added.begin(), added.end()));
    statusBar()->showMessage(tr("Pasted %1 and %2; %3 renamed, materials: %4 reused, %5 added")
                                 .arg(countedNoun(int(pasted.newSpheres.size()), ItemKind::Sphere),
                                      countedNoun(int(pasted.newLights.size()), ItemKind::Light))
                                 .arg(pasted.renamed)
                                 .arg(pasted.materialsReused)
                                 .arg(pasted.materialsAdded),
                             8000);
}

}  // namespace whitted::ui
