// GUI tests of the property panels as a newcomer meets them: refused edits in
// the user's words, the sphere's material on the sphere page with Make unique,
// material presets, and slider and arrow steps that suit a small ball. A shown
// MainWindow on the seed scene at 160x120.
#include <QAbstractItemView>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListView>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QTest>
#include <QUndoStack>
#include <QWheelEvent>

#include <memory>
#include <ostream>
#include <string>

#include "camera/camera_control.h"
#include "document/edit_messages.h"
#include "editor/main_window.h"
#include "panels/color_button.h"
#include "panels/material_sharing.h"
#include "panels/number_field.h"
#include "panels/scene_panel.h"
#include "scene/material_presets.h"
#include "scene/scene_io.h"
#include "support/main_window_fixture.h"
#include "support/test_support.h"
#include "viewport/render_view.h"

// Failures print a QString as its text.
inline void PrintTo(const QString& text, std::ostream* os) {
    *os << '"' << text.toStdString() << '"';
}

namespace whitted::ui {
namespace {

using test::preset;

class PropertyPanelsTest : public EditorWindowTest {
  protected:
    void SetUp() override {
        writeSeedFile();
        ASSERT_TRUE(showWindow({1200, 800}));
        ASSERT_TRUE(openAndWait(scenePath));
    }

    // Runs `act` (an edit through the widgets) and returns the frame it renders.
    QImage frameAfter(const std::function<void()>& act) {
        const int before = log->completed;
        act();
        EXPECT_TRUE(waitForRender(before));
        return window->renderView()->frame();
    }
    // Types `text` into a number field as a user does: select all, type, Return.
    static void typeInto(QAbstractSpinBox* field, const QString& text) {
        field->setFocus();
        field->selectAll();
        QTest::keyClicks(field, text);
        QTest::keyClick(field, Qt::Key_Return);
    }
    // The refused-edit message box, once it shows.
    QMessageBox* refusal() {
        QMessageBox* box = nullptr;
        const bool shown = QTest::qWaitFor([&] {
            box = window->findChild<QMessageBox*>(QStringLiteral("editRefusedMessage"));
            return box && box->isVisible();
        });
        if (!shown) return nullptr;
        return box;
    }
    // Of the pixels where sphere `sphere` (-1: none) is seen directly, how many
    // differ between two frames.
    struct PixelChange {
        int changed = 0, of = 0;
    };
    PixelChange changedPixelsOf(int sphere, const QImage& a, const QImage& b) {
        int changed = 0, count = 0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                if (pickSphere(doc->scene(), x + 0.5, y + 0.5).value_or(-1) != sphere) continue;
                ++count;
                changed += a.pixel(x, y) != b.pixel(x, y);
            }
        return {changed, count};
    }
    QString lastUndoText() { return doc->undoStack()->text(doc->undoStack()->count() - 1); }
};

// A typed radius of 0 is refused with the field's label and the
// sphere's name, and nothing changes.
TEST_F(PropertyPanelsTest, RadiusTypedZero_RefusedInUsersWords_SceneUnchanged) {
    window->scenePanel()->select(ItemKind::Sphere, kBlueBall);
    const Scene before = doc->scene();
    auto* radius = child<QDoubleSpinBox>("sphereRadius");
    typeInto(radius, QStringLiteral("0"));
    QMessageBox* box = refusal();
    ASSERT_NE(box, nullptr);
    EXPECT_EQ(box->text(), QStringLiteral("Radius of sphere “blue ball” must be greater than 0"));
    EXPECT_TRUE(doc->scene() == before);
    EXPECT_EQ(doc->undoStack()->count(), 0);
    EXPECT_EQ(radius->value(), 0.6) << "the field shows the sphere's radius again";
    box->close();
}

// The label of the form row that holds `field` (or a widget inside it).
QString rowLabelOf(QWidget* field) {
    for (QWidget* w = field; w && w->parentWidget(); w = w->parentWidget())
        if (auto* form = qobject_cast<QFormLayout*>(w->parentWidget()->layout()))
            if (auto* label = qobject_cast<QLabel*>(form->labelForField(w))) return label->text();
    return {};
}

// A field's row and its undo entry say it in the words of its one
// description (scene_fields.h): the row short where its page says the rest.
TEST_F(PropertyPanelsTest, FieldsRowAndUndoEntry_SayItInTheWordsOfItsDescription) {
    auto* fov = child<QDoubleSpinBox>("cameraVfov");
    EXPECT_EQ(rowLabelOf(fov), QStringLiteral("Vertical FOV:"));
    typeInto(fov, QStringLiteral("40"));
    ASSERT_EQ(doc->undoStack()->count(), 1);
    EXPECT_EQ(doc->undoStack()->text(0), QStringLiteral("Change vertical field of view"));
    EXPECT_EQ(doc->scene().camera.vfovDegrees, 40.0);

    auto* depth = child<QSpinBox>("renderMaxDepth");
    EXPECT_EQ(rowLabelOf(depth), QStringLiteral("Max depth:"));
    typeInto(depth, QStringLiteral("7"));
    ASSERT_EQ(doc->undoStack()->count(), 2);
    EXPECT_EQ(doc->undoStack()->text(1), QStringLiteral("Change max depth"));

    window->scenePanel()->select(ItemKind::Sphere, kBlueBall);
    auto* radius = child<QDoubleSpinBox>("sphereRadius");
    EXPECT_EQ(rowLabelOf(radius), QStringLiteral("Radius:"));
    typeInto(radius, QStringLiteral("0.5"));
    ASSERT_EQ(doc->undoStack()->count(), 3);
    EXPECT_EQ(doc->undoStack()->text(2), QStringLiteral("Change radius of blue ball"));
}

// Renaming a sphere to a taken name, in the list's own editor.
TEST_F(PropertyPanelsTest, RenameToTakenName_RefusedInUsersWords_SceneUnchanged) {
    window->scenePanel()->select(ItemKind::Sphere, kBlueBall);
    const Scene before = doc->scene();
    window->scenePanel()->renameAction()->trigger();
    auto* list = child<QListView>("sphereList");
    QLineEdit* editor = nullptr;
    ASSERT_TRUE(QTest::qWaitFor([&] { return (editor = list->findChild<QLineEdit*>()); }));
    editor->selectAll();
    QTest::keyClicks(editor, QStringLiteral("purple ball"));
    QTest::keyClick(editor, Qt::Key_Return);
    QMessageBox* box = refusal();
    ASSERT_NE(box, nullptr);
    EXPECT_EQ(box->text(), QStringLiteral("There is already a sphere named “purple ball”"));
    EXPECT_TRUE(doc->scene() == before);
    EXPECT_EQ(doc->undoStack()->count(), 0);
    box->close();
}

// The scene panel filters its list by name; what the buttons do
// applies to the item the filtered list shows, and an item picked elsewhere
// (the picture) that the filter hides is shown again.
TEST_F(PropertyPanelsTest, SceneFilter_ShowsMatchingNames_DeleteRemovesTheShownOne) {
    window->scenePanel()->select(ItemKind::Sphere, kBlueBall);
    auto* filter = child<QLineEdit>("sphereListFilter");
    auto* list = child<QListView>("sphereList");
    ASSERT_TRUE(filter && list);
    QTest::keyClicks(filter, QStringLiteral("PURP"));
    ASSERT_EQ(list->model()->rowCount(), 1);
    EXPECT_EQ(list->model()->index(0, 0).data().toString(), QStringLiteral("purple ball"));
    EXPECT_EQ(window->scenePanel()->currentIndex(), -1)
        << "the filter hides the selected blue ball: nothing stays selected";
    list->selectionModel()->setCurrentIndex(list->model()->index(0, 0),
                                            QItemSelectionModel::ClearAndSelect);
    EXPECT_EQ(window->scenePanel()->currentIndex(), kPurpleBall);
    window->scenePanel()->deleteAction()->trigger();
    std::vector<std::string> names;
    for (const Sphere& sp : doc->scene().spheres) names.push_back(sp.name);
    EXPECT_EQ(names, (std::vector<std::string>{"blue ball", "white ball", "floor"}));
    EXPECT_EQ(list->model()->rowCount(), 0);

    QTest::keyClicks(filter, QStringLiteral("x"));
    window->scenePanel()->select(ItemKind::Sphere, 1);  // the white ball, as a click in the view
    EXPECT_TRUE(filter->text().isEmpty());
    EXPECT_EQ(list->model()->rowCount(), 3);
    EXPECT_EQ(window->scenePanel()->currentIndex(), 1);
    EXPECT_EQ(list->currentIndex().data().toString(), QStringLiteral("white ball"));
}

// Every field an edit can break reads as a sentence about a named item.
TEST(EditMessages, EveryValidationProblem_NamesTheItemAndTheFieldLabel) {
    const Scene seed = test::seedScene();
    const std::pair<std::function<void(Scene&)>, const char*> cases[] = {
        {[](Scene& s) { s.spheres[0].radius = 0; },
         "Radius of sphere “blue ball” must be greater than 0"},
        {[](Scene& s) { s.spheres[1].name = ""; }, "A sphere needs a name"},
        {[](Scene& s) { s.spheres[0].material = "gone"; },
         "Sphere “blue ball” uses material “gone”, which does not exist"},
        {[](Scene& s) { s.materials[1].reflectivity = 2; },
         "Reflectivity of material “purple” must be between 0 and 1"},
        {[](Scene& s) { s.materials[0].ior = 0; },
         "Index of refraction of material “blue” must be greater than 0"},
        {[](Scene& s) { s.materials[3].checker->size = 0; },
         "Checker size of material “floor” must be greater than 0"},
        {[](Scene& s) { s.materials[0].diffuse.x = -1; },
         "Diffuse colour of material “blue” must not have negative components"},
        {[](Scene& s) { s.materials[2].name = "blue"; },
         "There is already a material named “blue”"},
        {[](Scene& s) { s.lights[0].intensity = -1; },
         "Intensity of light “key” must not be negative"},
        {[](Scene& s) { s.lights[0].position.y = INFINITY; },
         "Position of light “key” must be a finite number"},
        {[](Scene& s) { s.camera.lookAt = s.camera.position; },
         "The camera's look-at point must differ from its position"},
        {[](Scene& s) {
             s.camera.up = {0, 0, 0};
         },
         "The camera's up vector must not be zero"},
        {[](Scene& s) { s.camera.vfovDegrees = 180; },
         "Vertical field of view must be between 0 and 180 degrees"},
        {[](Scene& s) { s.render.width = 0; }, "Image width must be between 1 and 16384 pixels"},
        {[](Scene& s) { s.ambient.y = -0.5; }, "Ambient colour must not have negative components"},
    };
    for (const auto& [change, expected] : cases) {
        Scene s = seed;
        change(s);
        const auto problem = validateScene(s);
        ASSERT_TRUE(problem) << expected;
        EXPECT_EQ(editProblemText(*problem, s).toStdString(), expected);
    }
}

// Make unique's names count on from the original's.
TEST(MaterialSharing, CopyNames_CountOn_SharersCounted) {
    Scene s = test::seedScene();
    EXPECT_EQ(numberedMaterialName(s, "blue"), "blue 2");
    s.spheres[kPurpleBall].material = "blue";
    EXPECT_EQ(spheresUsing(s, "blue"), 2);
    makeMaterialUnique(s, kPurpleBall);
    EXPECT_EQ(s.spheres[kPurpleBall].material, "blue 2");
    EXPECT_EQ(spheresUsing(s, "blue"), 1);
    EXPECT_EQ(numberedMaterialName(s, "blue"), "blue 3");
    EXPECT_EQ(numberedMaterialName(s, "blue 2"), "blue 3") << "not \"blue 2 2\"";
    // Only a number after one space counts on; anything else gets " 2".
    EXPECT_EQ(numberedMaterialName(s, "blue 41"), "blue 42");
    EXPECT_EQ(numberedMaterialName(s, "blue  7"), "blue  7 2");
    EXPECT_EQ(numberedMaterialName(s, "blue 7a"), "blue 7a 2");
    EXPECT_EQ(numberedMaterialName(s, "blue 123456789"), "blue 123456789 2");
    EXPECT_EQ(numberedMaterialName(s, " 5"), " 5 2");
    EXPECT_EQ(numberedMaterialName(s, "glass\t 5"), "glass\t 5 2");
}

// The sphere page shows its material and who shares it.
TEST_F(PropertyPanelsTest, SpherePage_ShowsMaterialAndHowManySpheresShareIt) {
    window->scenePanel()->select(ItemKind::Sphere, kPurpleBall);
    auto* material = child<QComboBox>("sphereMaterial");
    auto* users = child<QLabel>("sphereMaterialUsers");
    EXPECT_EQ(material->currentText(), QStringLiteral("purple"));
    EXPECT_EQ(users->text(), QStringLiteral("Used by this sphere only"));
    EXPECT_FALSE(child<QPushButton>("sphereMakeUnique")->isEnabled());

    material->setCurrentIndex(material->findText(QStringLiteral("blue")));
    EXPECT_EQ(doc->scene().spheres[kPurpleBall].material, "blue");
    EXPECT_EQ(lastUndoText(), QStringLiteral("Change material of purple ball"));

    window->scenePanel()->select(ItemKind::Sphere, kBlueBall);
    EXPECT_EQ(users->text(), QStringLiteral("Shared by 2 spheres"));
    EXPECT_TRUE(child<QPushButton>("sphereMakeUnique")->isEnabled());
    EXPECT_EQ(child<ColorButton>("sphereMaterialDiffuse")->color(), Vec3(0, 0, 1));
    EXPECT_EQ(child<QDoubleSpinBox>("sphereMaterialReflectivity")->value(), 0.5);
    EXPECT_EQ(child<QDoubleSpinBox>("sphereMaterialTransparency")->value(), 0.0);
    EXPECT_TRUE(child<ColorButton>("sphereMaterialDiffuse")->isVisibleTo(window.get()));
}

// The colour on the sphere page is its material's; the ball turns red.
TEST_F(PropertyPanelsTest, SpherePageColour_EditsItsMaterial_BallPixelsChange) {
    window->scenePanel()->select(ItemKind::Sphere, kBlueBall);
    const QImage before = window->renderView()->frame();
    const QImage after =
        frameAfter([&] { child<ColorButton>("sphereMaterialDiffuse")->edit(Vec3(1, 0, 0)); });
    EXPECT_EQ(doc->scene().materials[0].diffuse, Vec3(1, 0, 0));
    EXPECT_EQ(lastUndoText(), QStringLiteral("Change diffuse colour of material blue"));
    const PixelChange ball = changedPixelsOf(kBlueBall, before, after);
    EXPECT_GT(ball.of, 200);
    EXPECT_GT(ball.changed, ball.of * 9 / 10);
    const PixelChange background = changedPixelsOf(-1, before, after);
    EXPECT_GT(background.of, 1000);
    EXPECT_EQ(background.changed, 0) << "the background stays";
}

// Make unique gives this ball a copy; a colour edit then changes it alone.
TEST_F(PropertyPanelsTest, MakeUnique_CopyForThisSphereOnly_OneUndoStep) {
    frameAfter([&] {
        ASSERT_TRUE(doc->edit(QStringLiteral("share"),
                              [](Scene& s) { s.spheres[kPurpleBall].material = "blue"; }));
    });
    window->scenePanel()->select(ItemKind::Sphere, kBlueBall);
    const int steps = doc->undoStack()->count();
    const QImage shared = frameAfter(
        [&] { QTest::mouseClick(child<QPushButton>("sphereMakeUnique"), Qt::LeftButton); });
    ASSERT_EQ(doc->scene().materials.size(), 5u);
    EXPECT_EQ(doc->scene().materials[4].name, "blue 2");
    EXPECT_EQ(doc->scene().materials[4].diffuse, Vec3(0, 0, 1));
    EXPECT_EQ(doc->scene().spheres[kBlueBall].material, "blue 2");
    EXPECT_EQ(doc->scene().spheres[kPurpleBall].material, "blue");
    EXPECT_EQ(doc->undoStack()->count(), steps + 1);
    EXPECT_EQ(lastUndoText(), QStringLiteral("Make material of blue ball unique"));
    EXPECT_EQ(child<QLabel>("sphereMaterialUsers")->text(),
              QStringLiteral("Used by this sphere only"));
    EXPECT_EQ(child<QComboBox>("sphereMaterial")->currentText(), QStringLiteral("blue 2"));

    const QImage red =
        frameAfter([&] { child<ColorButton>("sphereMaterialDiffuse")->edit(Vec3(1, 0, 0)); });
    EXPECT_EQ(doc->scene().materials[0].diffuse, Vec3(0, 0, 1)) << "the shared blue stays blue";
    const PixelChange ball = changedPixelsOf(kBlueBall, shared, red);
    EXPECT_GT(ball.changed, ball.of * 9 / 10);
    // The purple ball (now blue) reflects its neighbour at its edge, no more.
    const PixelChange other = changedPixelsOf(kPurpleBall, shared, red);
    EXPECT_GT(other.of, 200);
    EXPECT_LT(other.changed, other.of / 5);

    doc->undoStack()->undo();
    doc->undoStack()->undo();
    EXPECT_EQ(doc->scene().materials.size(), 4u);
    EXPECT_EQ(doc->scene().spheres[kBlueBall].material, "blue");
}

// The Preset combo applies each preset as one step, keeping the name.
TEST_F(PropertyPanelsTest, PresetCombo_EachPresetSetsItsValues_OneStepKeepsName) {
    window->scenePanel()->select(ItemKind::Material, 0);
    auto* combo = child<QComboBox>("materialPreset");
    EXPECT_EQ(combo->currentText(), QStringLiteral("Custom"));
    combo->setFocus();
    int steps = doc->undoStack()->count();
    for (const MaterialPreset& p : materialPresets()) {
        QTest::keyClick(combo, Qt::Key_Down);  // the next preset, as a user picks it
        const QString name = QString::fromUtf8(p.name.data(), qsizetype(p.name.size()));
        ASSERT_EQ(combo->currentText(), name);
        const Material& m = doc->scene().materials[0];
        EXPECT_EQ(m.name, "blue");
        EXPECT_EQ(m, withPreset(m, p)) << p.name;
        EXPECT_EQ(doc->undoStack()->count(), ++steps);
        EXPECT_EQ(lastUndoText(), QStringLiteral("Apply preset %1 to blue").arg(name));
    }
    EXPECT_EQ(doc->scene().materials[0].ior, 1.33) << "Water is last";
}

// A glass ball shows the floor through it.
TEST_F(PropertyPanelsTest, GlassPreset_BallShowsWhatIsBehindIt) {
    window->scenePanel()->select(ItemKind::Material, 0);
    auto* combo = child<QComboBox>("materialPreset");
    const QImage opaque = window->renderView()->frame();
    const QImage glass = frameAfter([&] {
        combo->setFocus();
        for (int i = 0; combo->currentText() != QStringLiteral("Glass") && i < 10; ++i)
            QTest::keyClick(combo, Qt::Key_Down);
    });
    EXPECT_EQ(doc->scene().materials[0].transparency, preset("Glass").transparency);
    const PixelChange ball = changedPixelsOf(kBlueBall, opaque, glass);
    EXPECT_GT(ball.changed, ball.of * 9 / 10);
    // The lower half of the ball looks at the floor: no longer a blue ball.
    int notBlue = 0, lower = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            if (pickSphere(doc->scene(), x + 0.5, y + 0.5).value_or(-1) != kBlueBall) continue;
            const QColor was = opaque.pixelColor(x, y), is = glass.pixelColor(x, y);
            if (was.blue() <= was.red() + 20) continue;  // not a blue pixel to start with
            ++lower;
            notBlue += is.blue() < is.red() + 20;
        }
    EXPECT_GT(lower, 100);
    EXPECT_GT(notBlue, lower / 3) << "through the glass the grey floor shows";
}

// Add on the materials tab offers the presets.
TEST_F(PropertyPanelsTest, AddMaterialMenu_Glass_AddsGlassMaterialAndShowsIt) {
    window->scenePanel()->select(ItemKind::Material, 0);
    QMenu* menu = child<QMenu>("addMaterialMenu");
    ASSERT_NE(menu, nullptr);
    QStringList offered;
    for (QAction* a : menu->actions())
        if (!a->isSeparator()) offered << a->text();
    EXPECT_EQ(offered,
              QStringList({"Plain", "Matte", "Plastic", "Mirror", "Chrome", "Glass", "Water"}));
    child<QAction>("addMaterialGlass")->trigger();
    ASSERT_EQ(doc->scene().materials.size(), 5u);
    const Material& glass = doc->scene().materials[4];
    EXPECT_EQ(glass.name, "glass");
    EXPECT_EQ(glass, presetMaterial(preset("Glass"), "glass"));
    EXPECT_EQ(lastUndoText(), QStringLiteral("Add material glass"));
    EXPECT_EQ(child<QLabel>("materialName")->text(), QStringLiteral("glass"));
    EXPECT_EQ(child<QComboBox>("materialPreset")->currentText(), QStringLiteral("Glass"));
    child<QAction>("addMaterialGlass")->trigger();
    EXPECT_EQ(doc->scene().materials.back().name, "glass 2");
}

// A 0.05 ball's radius slider moves a few percent a step, Shift finer;
// its centre's arrows move it by 0.01, Shift by 0.001.
TEST_F(PropertyPanelsTest, SmallBall_SliderAndArrowSteps_SmallAndFinerWithShift) {
    window->scenePanel()->select(ItemKind::Sphere, kBlueBall);
    auto* radius = child<QDoubleSpinBox>("sphereRadius");
    typeInto(radius, QStringLiteral("0.05"));
    ASSERT_EQ(doc->scene().spheres[kBlueBall].radius, 0.05);

    auto* slider = child<QSlider>("sphereRadiusSlider");
    slider->setFocus();
    QTest::keyClick(slider, Qt::Key_Right);
    const double r1 = doc->scene().spheres[kBlueBall].radius;
    const double step = (r1 - 0.05) / 0.05;
    EXPECT_GT(step, 0.0);
    EXPECT_LT(step, 0.10) << "one slider step changes a 0.05 radius by less than 10 %";
    QTest::keyClick(slider, Qt::Key_Right, Qt::ShiftModifier);
    const double fine = (doc->scene().spheres[kBlueBall].radius - r1) / r1;
    EXPECT_GT(fine, 0.0);
    EXPECT_LT(fine, step / 4) << "Shift steps finer";

    // Shift and the wheel: one slider position, a fraction of a percent.
    const double r3 = doc->scene().spheres[kBlueBall].radius;
    QWheelEvent wheel(QPointF(5, 5), slider->mapToGlobal(QPointF(5, 5)), QPoint(), QPoint(0, 120),
                      Qt::NoButton, Qt::ShiftModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(slider, &wheel);
    const double wheeled = (doc->scene().spheres[kBlueBall].radius - r3) / r3;
    EXPECT_GT(wheeled, 0.0);
    EXPECT_LT(wheeled, step / 4) << "Shift+wheel steps finely, not by a page";

    auto* x = child<QDoubleSpinBox>("sphereCenterX");
    const double x0 = doc->scene().spheres[kBlueBall].center.x;
    x->setFocus();
    QTest::keyClick(x, Qt::Key_Up);
    EXPECT_NEAR(doc->scene().spheres[kBlueBall].center.x - x0, 0.01, 1e-12);
    QTest::keyClick(x, Qt::Key_Up, Qt::ShiftModifier);
    EXPECT_NEAR(doc->scene().spheres[kBlueBall].center.x - x0, 0.011, 1e-12);

    const double r2 = doc->scene().spheres[kBlueBall].radius;
    radius->setFocus();
    QTest::keyClick(radius, Qt::Key_Up, Qt::ShiftModifier);
    EXPECT_NEAR(doc->scene().spheres[kBlueBall].radius - r2, 0.0001, 1e-12)
        << "Shift: a tenth of the 0.001 step";
}

}  // namespace
}  // namespace whitted::ui
