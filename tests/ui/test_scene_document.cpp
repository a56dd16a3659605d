// SceneDocument records each edit as the items it changed (not whole scenes):
// undoing and redoing any sequence of edits must still give back every scene
// exactly, structure changes (adds, deletes, renames) included.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QSignalSpy>
#include <QUndoStack>

#include <iostream>
#include <random>

#include "scene_document.h"
#include "scene_io.h"

namespace whitted::ui {
namespace {

TEST(SceneDocument, RandomEdits_UndoAndRedoGiveBackEveryScene) {
    SceneDocument doc;
    doc.reset(loadScene(WHITTED_SCENES_DIR "/seed.json"), QString());
    std::mt19937 rng(7);
    std::cout << "[ SEED     ] 7\n";
    auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
    std::vector<Scene> history{doc.scene()};
    for (int step = 0; step < 300; ++step) {
        const int kind = pick(6);
        ASSERT_TRUE(doc.edit("edit", [&](Scene& s) {
            const int n = int(s.spheres.size());
            switch (kind) {
                case 0:
                    s.spheres[pick(n)].radius = 0.1 + 0.01 * step;
                    break;
                case 1:
                    s.spheres[pick(n)].name = "renamed " + std::to_string(step);
                    break;
                case 2:
                    s.spheres.push_back(
                        Sphere{"new " + std::to_string(step), {0, 0, 3}, 0.2, "blue"});
                    break;
                case 3:
                    if (n > 1)
                        s.spheres.erase(s.spheres.begin() + pick(n));
                    else
                        s.spheres[0].radius = 0.3 + 0.001 * step;
                    break;
                case 4:
                    s.camera.position.x += 0.01;
                    s.lights[0].intensity = 0.5 + 0.001 * step;
                    break;
                default:
                    s.materials[pick(int(s.materials.size()))].specular = 0.001 * step;
            }
        }));
        history.push_back(doc.scene());
    }
    QSignalSpy structure(&doc, &SceneDocument::structureChanged);
    for (int i = int(history.size()) - 2; i >= 0; --i) {
        doc.undoStack()->undo();
        ASSERT_EQ(doc.scene(), history[i]) << "after undoing back to step " << i;
    }
    EXPECT_GT(structure.count(), 50);  // adds, deletes and renames were announced
    for (std::size_t i = 1; i < history.size(); ++i) {
        doc.undoStack()->redo();
        ASSERT_EQ(doc.scene(), history[i]) << "after redoing step " << i;
    }
}

}  // namespace
}  // namespace whitted::ui

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
