// What the parts of a plot's painting share (scatter_plot.cpp, plot_grid.cpp,
// plot_marks.cpp, plot_legend.cpp): its colours, the highlight ring's width and
// fonts scaled from the painter's. Internal to them.
#pragma once

#include <QColor>
#include <QFont>

#include <algorithm>
#include <cmath>

namespace whitted::ui::plot_painting {

// The highlight ring's width beyond the marker, in pixels.
inline constexpr double kRingWidth = 2.5;

inline const QColor kGridMajor(210, 210, 210);
inline const QColor kGridMinor(236, 236, 236);
inline const QColor kText(30, 30, 30);
inline const QColor kLegendMarker(110, 110, 110);

inline QFont scaledFont(QFont font, double factor) {
    if (font.pixelSize() > 0)
        font.setPixelSize(std::max(1, static_cast<int>(std::lround(font.pixelSize() * factor))));
    else
        font.setPointSizeF(font.pointSizeF() * factor);
    return font;
}

}  // namespace whitted::ui::plot_painting
