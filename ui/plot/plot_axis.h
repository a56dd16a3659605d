// One axis of a plot (ui/plot/scatter_plot.h): the range shown and where its ticks
// go, linear or logarithmic. Pure arithmetic, no painting, so the tests and the
// editor's hit-testing see the same mapping the painter uses.
#pragma once

#include <QString>

#include <vector>

namespace whitted::ui {

struct PlotAxis {
    double lo = 0.0, hi = 1.0;  // the range shown, in data units; lo < hi (both > 0 if log)
    bool log = false;
    std::vector<double> major;  // labelled ticks, ascending, inside [lo, hi]
    std::vector<double> minor;  // unlabelled ticks (a log axis's 2..9 of each decade)

    // Where v lies along the axis: 0 at lo, 1 at hi, outside [0, 1] beyond them.
    // NaN for a value the axis cannot show (not finite, or <= 0 on a log axis).
    double fraction(double v) const;
    // Whether fraction(v) is a number (the value can be placed on this axis).
    bool canShow(double v) const;
    // A tick's label: plain decimals, powers of ten with a superscript exponent
    // where plain digits would get long (log axes outside 1e-3 .. 1e5).
    QString label(double v) const;
};

// An axis covering [dataMin, dataMax] (values the axis cannot show left out by
// the caller) with a little room on either side. A log axis ticks whole decades,
// and 2 and 5 times them when the range holds fewer than two decades; a linear
// axis ticks at 1, 2 or 5 times a power of ten, about five to eight ticks, and is
// widened to its outer ticks. A log axis inside one decade with fewer than two
// of those multiples ticks plain numbers at such a step instead: every axis has
// at least two labelled ticks. An empty or single-valued range gets a sensible span.
PlotAxis makePlotAxis(double dataMin, double dataMax, bool log);

}  // namespace whitted::ui
