#include "document/settings_words.h"

#include <QObject>

namespace whitted::ui {

QString secondsText(double s) {
    if (s < 0.1) return QObject::tr("%1 ms").arg(s * 1000, 0, 'f', 1);
    if (s < 10) return QObject::tr("%1 s").arg(s, 0, 'f', 2);
    return QObject::tr("%1 s").arg(s, 0, 'f', 0);
}

QString precisionText(Precision p) {
    const auto name = precisionName(p);
    return QString::fromUtf8(name.data(), qsizetype(name.size()));
}

QString settingsText(int samples, int depth, Precision precision) {
    return QObject::tr("%1 spp, depth %2, %3")
        .arg(samples)
        .arg(depth)
        .arg(precisionText(precision));
}

QString settingsText(const RenderSettings& r) {
    return QObject::tr("%1, %2 × %3")
        .arg(settingsText(r.samplesPerPixel, r.maxDepth, r.precision))
        .arg(r.width)
        .arg(r.height);
}

}  // namespace whitted::ui
