#include "tradeoff_dock/tradeoff_points.h"
#include "document/settings_words.h"

#include <QObject>

#include <cmath>

namespace whitted::ui {

namespace {

QString scaleSuffix(double scale) {
    if (scale == 1.0) return {};
    if (scale == 0.5) return QStringLiteral(" ½");
    if (scale == 0.25) return QStringLiteral(" ¼");
    return QStringLiteral(" ×%1").arg(scale);
}

QString errorLines(const ErrorStats& e) {
    const QString psnr = std::isfinite(e.psnrSrgb8)
                             ? QObject::tr("%1 dB").arg(e.psnrSrgb8, 0, 'f', 1)
                             : QObject::tr("identical");
    return QObject::tr(
               "RMSE (8-bit sRGB): %1 of 255, PSNR %2\n"
               "RMSE (linear): %3\nLargest pixel difference: %4 of 255")
        .arg(e.rmseSrgb8, 0, 'f', 3)
        .arg(psnr)
        .arg(e.rmseLinear, 0, 'g', 3)
        .arg(e.largest, 0, 'f', 1);
}

}  // namespace

QString shortLabel(const TradeoffPoint& p) {
    const TradeoffSettings& s = p.settings;
    return QStringLiteral("%1 spp d%2 %3%4")
        .arg(s.samplesPerPixel)
        .arg(s.maxDepth)
        .arg(precisionText(s.precision))
        .arg(scaleSuffix(s.resolutionScale));
}

QString shortLabel(const PinnedPoint& p) {
    const RenderSettings& s = p.settings;
    return QStringLiteral("%1 spp d%2 %3")
        .arg(s.samplesPerPixel)
        .arg(s.maxDepth)
        .arg(precisionText(s.precision));
}

QString pointTooltip(const TradeoffPoint& p) {
    const TradeoffSettings& s = p.settings;
    return QObject::tr("Measure: %1\n%2 × %3 (scale %4)\nTime: %5 (median of %6), %7 Mrays/s\n%8%9")
        .arg(settingsText(s.samplesPerPixel, s.maxDepth, s.precision))
        .arg(p.width)
        .arg(p.height)
        .arg(s.resolutionScale)
        .arg(secondsText(p.seconds))
        .arg(p.runs)
        .arg(p.mraysPerSecond, 0, 'f', 1)
        .arg(errorLines(p.error))
        .arg(p.pareto ? QObject::tr("\nOn the Pareto front") : QString());
}

QString pointTooltip(const PinnedPoint& p) {
    const RenderSettings& s = p.settings;
    const double mrays = p.seconds > 0 ? double(p.rays) / p.seconds / 1e6 : 0.0;
    QString text = QObject::tr(
                       "Render %1 against the pinned image: %2\n%3 × %4\nTime: %5, %6 "
                       "Mrays/s\n")
                       .arg(p.id)
                       .arg(settingsText(s.samplesPerPixel, s.maxDepth, s.precision))
                       .arg(s.width)
                       .arg(s.height)
                       .arg(secondsText(p.seconds))
                       .arg(mrays, 0, 'f', 1);
    if (p.error) return text + errorLines(*p.error);
    return text + (p.note.isEmpty() ? QObject::tr("Error: being measured…") : p.note);
}

}  // namespace whitted::ui
