// GUI tests of Whitted's 1980 sampling in the editor: chosen under
// Antialiasing in the Render tab, the view shows core's render with it, bit
// for bit as 8-bit sRGB; View > Subdivision Map shows how deep each pixel
// was cut; a quality target and the sampler exclude each other.
#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QSpinBox>
#include <QStatusBar>
#include <QTest>

#include "document/quality_choice.h"
#include "image/heat_map.h"
#include "panels/number_field.h"
#include "support/main_window_fixture.h"

namespace whitted::ui {
namespace {

class Whitted1980ViewTest : public MainWindowTest {
  protected:
    RenderResult coreRender(Whitted1980Sampling sampling) const {
        RenderOptions options = oneShotOptions();
        options.whitted1980 = sampling;
        return render(doc->scene(), options);
    }

    // Chooses the sampler in the Render tab, then the complete frame it renders.
    ::testing::AssertionResult chooseWhitted1980() {
        const int before = log->completed;
        child<QComboBox>("renderSampler")->setCurrentIndex(1);
        return waitForRender(before);
    }

    bool statusSays(const QString& text) const {
        for (QLabel* label : window->statusBar()->findChildren<QLabel*>())
            if (label->text() == text) return true;
        return false;
    }
};

TEST_F(Whitted1980ViewTest, ChosenInTheRenderTab_TheViewShowsCoresPicture) {
    // The threshold's row is hidden until Whitted 1980 is chosen.
    ASSERT_TRUE(child<QDoubleSpinBox>("samplerThreshold")->isHidden());
    ASSERT_TRUE(chooseWhitted1980());
    EXPECT_FALSE(child<QDoubleSpinBox>("samplerThreshold")->isHidden());
    const RenderResult want = coreRender(Whitted1980Sampling{});
    EXPECT_TRUE(sameImage(view->frame(), toQImage(want.image)));
    EXPECT_TRUE(log->lastComplete.whitted1980.has_value());
    const double perPixel = double(want.rays.camera) / (kWidth * kHeight);
    EXPECT_TRUE(statusSays(
        QStringLiteral("Whitted 1980: %1 camera rays a pixel").arg(perPixel, 0, 'f', 2)));
    // Samples per pixel no longer count, and say so; nor do their predictions.
    EXPECT_FALSE(child<IntField>("renderSamples")->isEnabled());
    EXPECT_TRUE(child<QLabel>("predictedTime")->text().startsWith("none for Whitted 1980"))
        << child<QLabel>("predictedTime")->text().toStdString();

    // A finer threshold and more cuts: rendered again, with them.
    const int before = log->completed;
    child<QDoubleSpinBox>("samplerThreshold")->setValue(2.0);
    ASSERT_TRUE(waitForRender(before));
    const int again = log->completed;
    child<QSpinBox>("samplerSubdivisions")->setValue(3);
    ASSERT_TRUE(waitForRender(again));
    EXPECT_TRUE(sameImage(view->frame(), toQImage(coreRender({2.0, 3}).image)));
}

TEST_F(Whitted1980ViewTest, SubdivisionMap_ShowsHowDeepEachPixelWasCut_AndBack) {
    ASSERT_TRUE(chooseWhitted1980());
    const QImage picture = view->frame();
    QAction* map = child<QAction>("showSubdivisionMap");
    map->trigger();
    const RenderResult want = coreRender(Whitted1980Sampling{});
    EXPECT_TRUE(sameImage(view->frame(), toQImage(countMap(want.subdivision.levels, kWidth, kHeight,
                                                           Whitted1980Sampling{}.maxLevels))));
    // The sky at the top was not cut: black.
    EXPECT_EQ(view->frame().pixelColor(kWidth / 2, 1), QColor(Qt::black));
    map->trigger();
    EXPECT_TRUE(sameImage(view->frame(), picture));
}

TEST_F(Whitted1980ViewTest, AQualityTarget_SetsTheSamplerBack) {
    ASSERT_TRUE(chooseWhitted1980());
    QualityChoice* quality = window->qualityChoice();
    ASSERT_TRUE(quality->whitted1980().has_value());
    const int before = log->completed;
    window->findChild<QAction*>("presetDraft")->trigger();
    ASSERT_TRUE(waitForRender(before));
    EXPECT_FALSE(quality->whitted1980().has_value());
    EXPECT_EQ(child<QComboBox>("renderSampler")->currentIndex(), 0);
    EXPECT_FALSE(log->lastComplete.whitted1980.has_value());
    EXPECT_TRUE(child<QDoubleSpinBox>("samplerThreshold")->isHidden());
}

}  // namespace
}  // namespace whitted::ui
