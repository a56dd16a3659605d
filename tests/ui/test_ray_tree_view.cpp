// GUI tests of the Ray Tree dock: a Ctrl+click on a pixel of the shown
// window's view lists that pixel's ray tree and draws it over the picture.
// What the dock lists is checked against core's pixelRayTree() of the same
// scene and pixel, called directly: the same numbers, as the dock prints them.
#include <QAction>
#include <QDockWidget>
#include <QLabel>
#include <QSignalSpy>
#include <QTest>
#include <QTreeWidget>
#include <QTreeWidgetItemIterator>

#include <functional>

#include "analysis/pixel_ray_tree.h"
#include "ray_tree_dock/ray_tree_view.h"
#include "support/window_events.h"

namespace whitted::ui {
namespace {

// A tree is traced in microseconds, at nice 10 beside the main render: under a
// sanitizer with other tests busy on both cores, seconds.
constexpr int kTreeTimeoutMs = 30000;

enum Column { RayColumn, AddsColumn, OtherColumn, HitColumn, WeightColumn, DistanceColumn };

QString rgbText(const Vec3& c) {
    return QStringLiteral("%1, %2, %3").arg(c.r, 0, 'f', 4).arg(c.g, 0, 'f', 4).arg(c.b, 0, 'f', 4);
}

int countNodes(const RayTreeNode& node) {
    int n = 1;
    for (const RayTreeNode& child : node.children) n += countNodes(child);
    return n;
}

// The first node, depth first, that `wanted` accepts; its depth-first index in `index`.
const RayTreeNode* findNode(const RayTreeNode& node,
                            const std::function<bool(const RayTreeNode&)>& wanted, int& index) {
    if (wanted(node)) return &node;
    for (const RayTreeNode& child : node.children) {
        ++index;
        if (const RayTreeNode* found = findNode(child, wanted, index)) return found;
    }
    return nullptr;
}

class RayTreeViewTest : public WindowEventsTest {
  protected:
    void SetUp() override {
        WindowEventsTest::SetUp();
        if (HasFatalFailure()) return;
        rayTree = window->rayTreeView();
        dock = window->findChild<QDockWidget*>(QStringLiteral("rayTreeDock"));
        rows = window->findChild<QTreeWidget*>(QStringLiteral("rayTreeRows"));
        ASSERT_NE(rayTree, nullptr);
        ASSERT_NE(dock, nullptr);
        ASSERT_NE(rows, nullptr);
    }

    // The view point over pixel (x, y)'s centre.
    QPoint overPixel(QPoint pixel) const {
        return widgetPoint(QPointF(pixel.x() + 0.5, pixel.y() + 0.5));
    }

    // Ctrl+click on the pixel, then the tree it lists.
    ::testing::AssertionResult inspect(QPoint pixel) {
        QSignalSpy shown(rayTree, &RayTreeView::treeShown);
        click(overPixel(pixel), Qt::ControlModifier);
        return waitFor(shown);
    }

    static ::testing::AssertionResult waitFor(QSignalSpy& shown) {
        if (shown.isEmpty() && !shown.wait(kTreeTimeoutMs))
            return ::testing::AssertionFailure() << "no tree within " << kTreeTimeoutMs << " ms";
        return ::testing::AssertionSuccess();
    }

    // An edit, then the tree the dock traces again for it.
    ::testing::AssertionResult editAndRetrace(const std::function<void(Scene&)>& change) {
        QSignalSpy shown(rayTree, &RayTreeView::treeShown);
        if (auto edited = editAndWait(change); !edited) return edited;
        return waitFor(shown);
    }

    // The listed rays (not the cut-off rows), depth first.
    std::vector<QTreeWidgetItem*> rayRows() const {
        std::vector<QTreeWidgetItem*> found;
        for (QTreeWidgetItemIterator it(rows); *it; ++it)
            if ((*it)->data(RayColumn, Qt::UserRole).toInt() >= 0) found.push_back(*it);
        return found;
    }

    // A pixel on the lower half of the blue ball: its reflection hits the floor.
    QPoint blueBallPixel() const {
        const Sphere& ball = doc->scene().spheres[kBlueBall];
        return pixelOf(doc->scene(), ball.center - Vec3(0, 0.4 * ball.radius, 0));
    }

    QImage viewPicture() const {
        return view->grab().toImage().convertToFormat(QImage::Format_RGB32);
    }

    RayTreeView* rayTree = nullptr;
    QDockWidget* dock = nullptr;
    QTreeWidget* rows = nullptr;
};

TEST_F(RayTreeViewTest, CtrlClickOnABall_ShowsTheDockListingEveryRayAsTheCoreTracesIt) {
    ASSERT_FALSE(dock->isVisible());
    const std::vector<int> selected = doc->selection()->indices();
    const QPoint pixel = blueBallPixel();
    ASSERT_TRUE(inspect(pixel));
    EXPECT_TRUE(dock->isVisible());
    ASSERT_EQ(rayTree->pixel(), pixel);
    // The click inspected: the selection is as it was.
    EXPECT_EQ(doc->selection()->indices(), selected);

    const PixelRayTree want = pixelRayTree(doc->scene(), pixel.x(), pixel.y());
    const std::vector<QTreeWidgetItem*> listed = rayRows();
    ASSERT_EQ(int(listed.size()), countNodes(want.root));
    EXPECT_EQ(listed[0]->text(RayColumn), "Camera");
    EXPECT_EQ(listed[0]->text(HitColumn), "blue ball, entering");
    EXPECT_EQ(listed[0]->text(AddsColumn), rgbText(want.root.contribution));
    EXPECT_EQ(listed[0]->text(DistanceColumn), QString::number(want.root.t, 'g', 5));
    // The seed's one light first under the hit, then the reflection, which meets the floor.
    EXPECT_EQ(listed[1]->text(RayColumn), "Shadow to key");
    EXPECT_EQ(listed[1]->text(HitColumn), "the light, unblocked");
    int index = 0;
    const RayTreeNode* reflection = findNode(
        want.root, [](const RayTreeNode& n) { return n.kind == RayTreeNode::Kind::Reflection; },
        index);
    ASSERT_NE(reflection, nullptr);
    EXPECT_EQ(listed[index]->text(RayColumn), "Reflection");
    EXPECT_TRUE(listed[index]->text(HitColumn).startsWith("floor"))
        << listed[index]->text(HitColumn).toStdString();
    EXPECT_EQ(listed[index]->text(WeightColumn), QString::number(reflection->weight, 'g', 4));
    EXPECT_EQ(listed[index]->text(AddsColumn), rgbText(reflection->contribution));
    // The pixel's value: the render's, in the scene's precision; double beside it.
    const QString summary = window->findChild<QLabel*>("rayTreeSummary")->text();
    EXPECT_TRUE(summary.contains(rgbText(want.value))) << summary.toStdString();
    const PixelRayTree inDouble =
        pixelRayTree(doc->scene(), pixel.x(), pixel.y(), Precision::Double);
    EXPECT_TRUE(summary.contains(rgbText(inDouble.value))) << summary.toStdString();
    EXPECT_EQ(rows->headerItem()->text(OtherColumn), "In double");
    EXPECT_EQ(listed[0]->text(OtherColumn), rgbText(inDouble.root.contribution));
}

TEST_F(RayTreeViewTest, AnEdit_TracesTheSamePixelAgain) {
    const QPoint pixel = blueBallPixel();
    ASSERT_TRUE(inspect(pixel));
    const QString before = rayRows()[0]->text(AddsColumn);
    ASSERT_TRUE(editAndRetrace([](Scene& s) { s.materials[0].diffuse = Vec3(1, 0, 0); }));
    const PixelRayTree want = pixelRayTree(doc->scene(), pixel.x(), pixel.y());
    EXPECT_EQ(rayRows()[0]->text(AddsColumn), rgbText(want.root.contribution));
    EXPECT_NE(rayRows()[0]->text(AddsColumn), before);
    EXPECT_EQ(rayTree->pixel(), pixel);
}

TEST_F(RayTreeViewTest, DepthZero_ListsTheCutOffReflectionWithWhatItWouldAdd) {
    const QPoint pixel = blueBallPixel();
    ASSERT_TRUE(inspect(pixel));
    ASSERT_TRUE(editAndRetrace([](Scene& s) { s.render.maxDepth = 0; }));
    const PixelRayTree want = pixelRayTree(doc->scene(), pixel.x(), pixel.y());
    ASSERT_TRUE(want.root.cutOff);
    QTreeWidgetItem* camera = rows->topLevelItem(0);
    ASSERT_NE(camera, nullptr);
    QTreeWidgetItem* cut = nullptr;
    for (int i = 0; i < camera->childCount(); ++i)
        if (camera->child(i)->data(RayColumn, Qt::UserRole).toInt() < 0) cut = camera->child(i);
    ASSERT_NE(cut, nullptr);
    EXPECT_EQ(cut->text(RayColumn), "Cut off at depth 0");
    EXPECT_EQ(cut->text(AddsColumn), "would add " + rgbText(want.root.pastDepth));
    EXPECT_GT(want.root.pastDepth.b, 0.0);  // the floor and the sky it would have shown
}

TEST_F(RayTreeViewTest, APixelOfSky_IsOneCameraRayThatHitsNothing) {
    ASSERT_TRUE(inspect(QPoint(kWidth / 2, 2)));
    const std::vector<QTreeWidgetItem*> listed = rayRows();
    ASSERT_EQ(listed.size(), 1u);
    EXPECT_EQ(listed[0]->text(HitColumn), "nothing: the sky");
    const PixelRayTree want = pixelRayTree(doc->scene(), kWidth / 2, 2);
    EXPECT_EQ(listed[0]->text(AddsColumn), rgbText(want.value));
}

TEST_F(RayTreeViewTest, TheRaysAreDrawnOverThePicture_TheSelectedOneHighlighted_GoneWithTheDock) {
    const QImage plain = viewPicture();
    const QPoint pixel = blueBallPixel();
    ASSERT_TRUE(inspect(pixel));
    QTest::qWait(50);
    const QImage withRays = viewPicture();
    EXPECT_FALSE(identical(withRays, plain));

    // Where the reflection from the ball to the floor is drawn: its middle.
    const PixelRayTree tree = pixelRayTree(doc->scene(), pixel.x(), pixel.y());
    int index = 0;
    const RayTreeNode* reflection = findNode(
        tree.root, [](const RayTreeNode& n) { return n.kind == RayTreeNode::Kind::Reflection; },
        index);
    ASSERT_NE(reflection, nullptr);
    const QPoint middle =
        drawn(reflection->origin + reflection->direction * (reflection->t / 2)).toPoint();
    const QColor colour = rayColour(RayTreeNode::Kind::Reflection);
    const auto near = [](QColor a, QColor b) {
        return std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) +
                   std::abs(a.blue() - b.blue()) <
               60;
    };
    const auto seen = [&](const QImage& image, QColor wanted) {
        for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx)
                if (near(image.pixelColor(middle + QPoint(dx, dy)), wanted)) return true;
        return false;
    };
    EXPECT_TRUE(seen(withRays, colour))
        << "no reflection colour at " << middle.x() << "," << middle.y();
    EXPECT_FALSE(seen(plain, colour));

    // Selecting its row draws it wider, edged in white: across its middle
    // the picture changes on both sides of the line, and nowhere away from it.
    rows->setCurrentItem(rayRows()[index]);
    EXPECT_EQ(rayTree->highlightedRay(), index);
    QTest::qWait(50);
    const QImage highlighted = viewPicture();
    int changed = 0;
    for (int dx = -6; dx <= 6; ++dx)
        changed +=
            highlighted.pixel(middle + QPoint(dx, 0)) != withRays.pixel(middle + QPoint(dx, 0));
    EXPECT_GE(changed, 4);
    EXPECT_EQ(highlighted.pixel(middle - QPoint(30, 0)), withRays.pixel(middle - QPoint(30, 0)));
    EXPECT_TRUE(seen(highlighted, colour));

    // Closing the dock takes the rays off the picture.
    window->findChild<QAction*>("toggleRayTreeView")->trigger();
    EXPECT_FALSE(dock->isVisible());
    QTest::qWait(50);
    EXPECT_FALSE(seen(viewPicture(), colour));
    EXPECT_TRUE(rayTree->rays().size() > 1);  // kept for when it opens again
}

TEST_F(RayTreeViewTest, ADoubleScene_ComparesWithFloat) {
    const QPoint pixel = blueBallPixel();
    ASSERT_TRUE(inspect(pixel));
    ASSERT_TRUE(editAndRetrace([](Scene& s) { s.render.precision = Precision::Double; }));
    EXPECT_EQ(rows->headerItem()->text(OtherColumn), "In float");
    const PixelRayTree inFloat = pixelRayTree(doc->scene(), pixel.x(), pixel.y(), Precision::Float);
    const PixelRayTree inDouble = pixelRayTree(doc->scene(), pixel.x(), pixel.y());
    EXPECT_EQ(rayRows()[0]->text(AddsColumn), rgbText(inDouble.root.contribution));
    EXPECT_EQ(rayRows()[0]->text(OtherColumn), rgbText(inFloat.root.contribution));
}

TEST_F(RayTreeViewTest, TheHelpAndTheViewMenuSayHow) {
    QAction* toggle = window->findChild<QAction*>("toggleRayTreeView");
    ASSERT_NE(toggle, nullptr);
    EXPECT_EQ(toggle->shortcut(), QKeySequence(QStringLiteral("Ctrl+Shift+R")));
    bool listed = false;
    for (const auto& [gesture, effect] : RenderView::mouseControls())
        if (gesture == "Ctrl+click" && effect.contains("Ray Tree")) listed = true;
    EXPECT_TRUE(listed);
    key(Qt::Key_R, Qt::ControlModifier | Qt::ShiftModifier);
    EXPECT_TRUE(dock->isVisible());
    EXPECT_TRUE(window->findChild<QLabel*>("rayTreeSummary")->text().contains("Ctrl+click"));
}

}  // namespace
}  // namespace whitted::ui
