#include "plot/plot_axis.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace whitted::ui {

namespace {

// Rounding slack when asking whether a tick lies inside the range: 10^k computed
// through pow must count as inside a range that ends exactly at it.
constexpr double kSlack = 1e-9;
// More labelled ticks than this crowd a plot a few hundred pixels wide.
constexpr int kMaxMajorTicks = 8;

QString superscript(int n) {
    static const char16_t kDigits[] = u"⁰¹²³⁴⁵⁶⁷⁸⁹";
    QString digits = QString::number(std::abs(n));
    QString out = n < 0 ? QString(QChar(u'⁻')) : QString();
    for (QChar c : digits) out += QChar(kDigits[c.digitValue()]);
    return out;
}

// 1, 2 or 5 times a power of ten, near `raw`.
double niceStep(double raw) {
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    const double norm = raw / magnitude;
    const double nice = norm < 1.5 ? 1.0 : norm < 3.0 ? 2.0 : norm < 7.0 ? 5.0 : 10.0;
    return nice * magnitude;
}

// Ticks at 1, 2 or 5 times a power of ten inside [lo, hi], at least two of them.
std::vector<double> linearTicksWithin(double lo, double hi) {
    std::vector<double> ticks;
    for (double parts = 4.0; ticks.size() < 2; parts *= 2.0) {
        ticks.clear();
        const double step = niceStep((hi - lo) / parts);
        for (double k = std::ceil(lo / step); k * step <= hi; k += 1.0) ticks.push_back(k * step);
    }
    return ticks;
}

PlotAxis linearAxis(double dataMin, double dataMax) {
    if (!(dataMin <= dataMax)) dataMin = 0.0, dataMax = 1.0;
    if (dataMax - dataMin <= std::abs(dataMax) * 1e-12) {
        const double half = dataMin == 0.0 ? 1.0 : std::abs(dataMin) * 0.1;
        dataMin -= half, dataMax += half;
    }
    // A little room so that points on the outer ticks are not drawn on the frame.
    const double pad = (dataMax - dataMin) * 0.02;
    dataMin -= pad, dataMax += pad;
    const double step = niceStep((dataMax - dataMin) / 5.0);
    PlotAxis axis;
    axis.lo = std::floor(dataMin / step) * step;
    axis.hi = std::ceil(dataMax / step) * step;
    const int count = static_cast<int>(std::lround((axis.hi - axis.lo) / step));
    for (int i = 0; i <= count; ++i) {
        const double v = axis.lo + i * step;
        axis.major.push_back(std::abs(v) < step * 1e-9 ? 0.0 : v);
    }
    return axis;
}

PlotAxis logAxis(double dataMin, double dataMax) {
    if (!(dataMin > 0.0 && dataMin <= dataMax)) dataMin = 1.0, dataMax = 10.0;
    double a = std::log10(dataMin), b = std::log10(dataMax);
    if (b - a < 1e-9) a -= 0.5, b += 0.5;
    const double pad = std::max(0.04 * (b - a), 0.04);
    a -= pad, b += pad;
    PlotAxis axis;
    axis.log = true;
    axis.lo = std::pow(10.0, a);
    axis.hi = std::pow(10.0, b);

    const int firstDecade = static_cast<int>(std::ceil(a - kSlack));
    const int lastDecade = static_cast<int>(std::floor(b + kSlack));
    const int decades = lastDecade - firstDecade + 1;
    auto inside = [&](double v) {
        const double l = std::log10(v);
        return l >= a - kSlack && l <= b + kSlack;
    };
    if (decades >= 2) {
        // Every step-th decade labelled; the rest and the 2..9 multiples as minor
        // ticks while they stay a few pixels apart.
        const int step = (decades + kMaxMajorTicks - 1) / kMaxMajorTicks;
        for (int k = firstDecade - 1; k <= lastDecade; ++k) {
            const double decade = std::pow(10.0, k);
            if (k >= firstDecade) {
                const bool labelled = ((k % step) + step) % step == 0;
                (labelled ? axis.major : axis.minor).push_back(decade);
            }
            if (b - a > 12.0) continue;
            for (int m = 2; m <= 9; ++m)
                if (inside(m * decade)) axis.minor.push_back(m * decade);
        }
    } else {
        // Less than two decades: label 1, 2 and 5 times them, or every multiple
        // when even those are fewer than two.
        const int k0 = static_cast<int>(std::floor(a)) - 1, k1 = static_cast<int>(std::ceil(b));
        for (bool all : {false, true}) {
            axis.major.clear(), axis.minor.clear();
            for (int k = k0; k <= k1; ++k)
                for (int m = 1; m <= 9; ++m) {
                    const double v = m * std::pow(10.0, k);
                    if (!inside(v)) continue;
                    const bool labelled = all || m == 1 || m == 2 || m == 5;
                    (labelled ? axis.major : axis.minor).push_back(v);
                }
            if (axis.major.size() >= 2) break;
        }
        // Well inside one decade (1.2 .. 1.8): plain numbers at a nice step.
        if (axis.major.size() < 2) {
            axis.minor.clear();
            axis.major = linearTicksWithin(axis.lo, axis.hi);
        }
    }
    std::sort(axis.major.begin(), axis.major.end());
    std::sort(axis.minor.begin(), axis.minor.end());
    return axis;
}

}  // namespace

double PlotAxis::fraction(double v) const {
    if (!std::isfinite(v) || (log && v <= 0.0)) return std::numeric_limits<double>::quiet_NaN();
    if (log) return (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo));
    return (v - lo) / (hi - lo);
}

bool PlotAxis::canShow(double v) const {
    return !std::isnan(fraction(v));
}

QString PlotAxis::label(double v) const {
    if (!log) return QString::number(v, 'g', 6);
    const int e = static_cast<int>(std::floor(std::log10(v) + kSlack));
    if (e >= -3 && e <= 5) return QString::number(v, 'g', 8);
    const double mantissa = v / std::pow(10.0, e);
    const QString power = QStringLiteral("10") + superscript(e);
    // 'g' 3: a plain-number tick's mantissa (1.2) as well as a whole one (2).
    return std::abs(mantissa - 1.0) < 1e-6
               ? power
               : QString::number(mantissa, 'g', 3) + QChar(u'×') + power;
}

PlotAxis makePlotAxis(double dataMin, double dataMax, bool log) {
    return log ? logAxis(dataMin, dataMax) : linearAxis(dataMin, dataMax);
}

}  // namespace whitted::ui
