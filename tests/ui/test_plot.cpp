// Tests of the QPainter plots (ui/plot/scatter_plot.h, ui/plot/plot_axis.h), drawn
// offscreen into images: the axis arithmetic, that a plot paints something,
// and that a point lands on the pixel the layout says, in the colours promised.
#include <QGuiApplication>
#include <QPainter>

#include <cmath>

#include <gtest/gtest.h>

#include "plot/plot_axis.h"
#include "plot/scatter_plot.h"

namespace whitted::ui {
namespace {

// Largest channel difference between two colours.
int colourDistance(QColor a, QColor b) {
    return std::max({std::abs(a.red() - b.red()), std::abs(a.green() - b.green()),
                     std::abs(a.blue() - b.blue())});
}

TEST(PlotAxis, LogAxis_TicksWholeDecadesAndSpacesThemEvenly) {
    const PlotAxis axis = makePlotAxis(0.01, 1000.0, true);
    EXPECT_LE(axis.lo, 0.01);
    EXPECT_GE(axis.hi, 1000.0);
    ASSERT_EQ(axis.major.size(), 6u);
    for (std::size_t i = 0; i < axis.major.size(); ++i)
        EXPECT_NEAR(axis.major[i], std::pow(10.0, int(i) - 2), 1e-12 * axis.major[i]);
    const double decade = axis.fraction(100.0) - axis.fraction(10.0);
    EXPECT_GT(decade, 0.0);
    EXPECT_NEAR(axis.fraction(1000.0) - axis.fraction(100.0), decade, 1e-12);
    EXPECT_NEAR(axis.fraction(0.1) - axis.fraction(0.01), decade, 1e-12);
    EXPECT_FALSE(axis.canShow(0.0));
    EXPECT_FALSE(axis.canShow(-1.0));
    EXPECT_FALSE(axis.canShow(INFINITY));
    EXPECT_EQ(axis.label(0.001), QStringLiteral("0.001"));
    EXPECT_EQ(axis.label(100.0), QStringLiteral("100"));
    EXPECT_EQ(axis.label(1e-7), QStringLiteral("10⁻⁷"));
}

TEST(PlotAxis, NarrowLogAxis_StillHasTwoLabelledTicks) {
    const PlotAxis axis = makePlotAxis(2.2, 4.1, true);
    EXPECT_GE(axis.major.size(), 2u);
    for (double v : axis.major) {
        EXPECT_GE(v, axis.lo);
        EXPECT_LE(v, axis.hi);
    }
}

// The labels a reader sees on `axis`, in order.
QStringList labelsOf(const PlotAxis& axis) {
    QStringList labels;
    for (double v : axis.major) labels << axis.label(v);
    return labels;
}

TEST(PlotAxis, LogAxisSpanning2To5Ms_LabelsTwoAndFiveMs) {
    const PlotAxis axis = makePlotAxis(0.002, 0.005, true);
    EXPECT_EQ(labelsOf(axis), QStringList({QStringLiteral("0.002"), QStringLiteral("0.005")}));
}

// Render times of 1.2 to 1.8 s hold no 1, 2 or 5 and no other whole multiple:
// plain numbers at a nice step instead, never an axis without a label.
TEST(PlotAxis, LogAxisWithinOneDecadeWithoutWholeMultiples_LabelsPlainNumbers) {
    const PlotAxis axis = makePlotAxis(1.2, 1.8, true);
    EXPECT_EQ(labelsOf(axis), QStringList({QStringLiteral("1.2"), QStringLiteral("1.4"),
                                           QStringLiteral("1.6"), QStringLiteral("1.8")}));
    for (double v : axis.major) {
        EXPECT_GE(v, axis.lo);
        EXPECT_LE(v, axis.hi);
    }
    EXPECT_TRUE(axis.minor.empty());
    // The same far from 1, where labels carry a power of ten.
    const PlotAxis tiny = makePlotAxis(1.2e-7, 1.8e-7, true);
    ASSERT_GE(tiny.major.size(), 2u);
    EXPECT_EQ(tiny.label(tiny.major[0]), QStringLiteral("1.2×10⁻⁷"));
}

TEST(PlotAxis, LinearAxis_NiceTicksCoveringTheData) {
    const PlotAxis axis = makePlotAxis(0.3, 9.7, false);
    EXPECT_LE(axis.lo, 0.3);
    EXPECT_GE(axis.hi, 9.7);
    ASSERT_GE(axis.major.size(), 4u);
    ASSERT_LE(axis.major.size(), 9u);
    const double step = axis.major[1] - axis.major[0];
    for (std::size_t i = 1; i < axis.major.size(); ++i)
        EXPECT_NEAR(axis.major[i] - axis.major[i - 1], step, 1e-9);
    EXPECT_DOUBLE_EQ(axis.fraction(axis.lo), 0.0);
    EXPECT_DOUBLE_EQ(axis.fraction(axis.hi), 1.0);
}

TEST(PlotAxis, EmptyOrSingleValue_GivesAUsableRange) {
    for (bool log : {false, true}) {
        const PlotAxis single = makePlotAxis(5.0, 5.0, log);
        EXPECT_LT(single.lo, 5.0);
        EXPECT_GT(single.hi, 5.0);
        const PlotAxis empty = makePlotAxis(INFINITY, -INFINITY, log);
        EXPECT_LT(empty.lo, empty.hi);
        EXPECT_GE(empty.major.size(), 2u);
    }
}

TEST(ScatterPlot, PaintsAxesAndPointsOnWhite) {
    PlotSpec spec;
    spec.title = QStringLiteral("Error against time");
    spec.xLabel = QStringLiteral("seconds");
    spec.yLabel = QStringLiteral("RMSE");
    spec.logX = spec.logY = true;
    spec.series = {{QStringLiteral("float"), {}}, {QStringLiteral("double"), {}}};
    for (int i = 0; i < 20; ++i)
        spec.points.push_back({std::pow(2.0, i * 0.5), 100.0 / (i + 1), {}, i % 5 == 0, i % 2, 0});
    spec.lines.push_back({QStringLiteral("front"), Qt::black, {{1, 100}, {8, 20}, {512, 5}}});
    const QImage image = renderPlot(spec, QSize(640, 400));
    ASSERT_EQ(image.size(), QSize(640, 400));
    int white = 0, dark = 0, coloured = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (c == Qt::white) ++white;
            if (c.lightness() < 80) ++dark;
            if (colourDistance(c, plotPaletteColour(0)) < 20) ++coloured;
        }
    EXPECT_GT(white, image.width() * image.height() / 2) << "mostly white background";
    EXPECT_GT(dark, 500) << "axes, ticks and text";
    EXPECT_GT(coloured, 20) << "the float series' points";
}

TEST(ScatterPlot, HighlightedPoint_HasRingColourAroundSeriesColourWhereLayoutSays) {
    PlotSpec spec;
    spec.xLabel = QStringLiteral("x");
    spec.yLabel = QStringLiteral("y");
    spec.xRange = {{0.0, 10.0}};
    spec.yRange = {{0.0, 10.0}};
    spec.series = {{QStringLiteral("a"), QColor(0, 0, 255)}};
    spec.highlightColour = QColor(255, 0, 0);
    spec.pointRadius = 5.0;
    spec.points.push_back({5.0, 5.0, {}, true, 0, 0});
    spec.points.push_back({2.0, 8.0, {}, false, 0, 0});
    const QSize size(400, 300);
    const QImage image = renderPlot(spec, size);
    const PlotLayout layout = plotLayout(QRectF(QPointF(0, 0), QSizeF(size)), spec, plotFont(size));

    // A linear axis: (5, 5) is in the middle of the range the axis shows.
    const QPointF c = layout.map(5.0, 5.0);
    EXPECT_NEAR(c.x(), layout.area.left() + layout.x.fraction(5.0) * layout.area.width(), 1e-9);
    EXPECT_NEAR(layout.x.fraction(5.0), (5.0 - layout.x.lo) / (layout.x.hi - layout.x.lo), 1e-12);
    const int cx = static_cast<int>(std::floor(c.x())), cy = static_cast<int>(std::floor(c.y()));
    EXPECT_LE(colourDistance(image.pixelColor(cx, cy), QColor(0, 0, 255)), 8)
        << "centre " << cx << "," << cy;
    // Inside the ring: between the marker's radius (5) and the ring's (7.5).
    const int ring = static_cast<int>(std::lround(spec.pointRadius + 1.25));
    for (auto [dx, dy] : {std::pair{ring, 0}, std::pair{-ring, 0}, std::pair{0, ring}})
        EXPECT_LE(colourDistance(image.pixelColor(cx + dx, cy + dy), QColor(255, 0, 0)), 40)
            << "ring at offset " << dx << "," << dy;
    // The ordinary point: its colour, and no ring.
    const QPointF o = layout.map(2.0, 8.0);
    const int ox = static_cast<int>(std::floor(o.x())), oy = static_cast<int>(std::floor(o.y()));
    EXPECT_LE(colourDistance(image.pixelColor(ox, oy), QColor(0, 0, 255)), 60);
    EXPECT_GT(colourDistance(image.pixelColor(ox + ring, oy), QColor(255, 0, 0)), 100);
}

TEST(ScatterPlot, LogAxes_PutTenAndHundredADecadeApart) {
    PlotSpec spec;
    spec.logX = spec.logY = true;
    spec.legend = LegendPlacement::None;
    spec.points = {{10.0, 10.0, {}, false, 0, 0},
                   {100.0, 100.0, {}, false, 0, 0},
                   {1000.0, 1000.0, {}, false, 0, 0}};
    const QSize size(500, 500);
    const PlotLayout layout = plotLayout(QRectF(QPointF(0, 0), QSizeF(size)), spec, plotFont(size));
    const QPointF p10 = layout.map(10, 10), p100 = layout.map(100, 100),
                  p1000 = layout.map(1000, 1000);
    EXPECT_GT(p100.x() - p10.x(), 50.0);
    EXPECT_NEAR(p100.x() - p10.x(), p1000.x() - p100.x(), 1e-6);
    EXPECT_NEAR(p10.y() - p100.y(), p100.y() - p1000.y(), 1e-6);
    EXPECT_TRUE(layout.area.contains(p10) && layout.area.contains(p1000));
    // And the pixels agree: the painted points sit where the layout maps them.
    const QImage image = renderPlot(spec, size);
    for (const QPointF& p : {p10, p100, p1000})
        EXPECT_LE(colourDistance(image.pixelColor(int(p.x()), int(p.y())), plotPaletteColour(0)),
                  60)
            << p.x() << "," << p.y();
    // pointNear finds the one under the cursor.
    EXPECT_EQ(pointNear(layout, spec, p100 + QPointF(2, 1), 6.0), std::optional<std::size_t>(1));
    EXPECT_EQ(pointNear(layout, spec, p100 + QPointF(40, 0), 6.0), std::nullopt);
}

TEST(ScatterPlot, UnshowableValuesAreLeftOut) {
    PlotSpec spec;
    spec.logY = true;
    spec.points = {
        {1.0, 0.0, {}, false, 0, 0}, {2.0, INFINITY, {}, false, 0, 0}, {3.0, 5.0, {}, false, 0, 0}};
    spec.lines.push_back({{}, Qt::black, {{1, 0}, {2, 3}, {3, 5}}});
    const QImage image = renderPlot(spec, QSize(300, 200));
    EXPECT_FALSE(image.isNull());
    const PlotLayout layout = plotLayout(QRectF(0, 0, 300, 200), spec, plotFont({300, 200}));
    EXPECT_TRUE(std::isnan(layout.map(1.0, 0.0).y()));
    EXPECT_LE(layout.y.lo, 3.0);
    EXPECT_GE(layout.y.hi, 5.0);
}

}  // namespace
}  // namespace whitted::ui
