#include "editor/window_placement.h"

#include <QGuiApplication>
#include <QScreen>

#include <algorithm>

namespace whitted::ui {

QSize firstWindowSize(QSize available) {
    return QSize(1400, 860).boundedTo(available * 0.9);
}

bool someScreenShows(const QRect& geometry) {
    const auto screens = QGuiApplication::screens();
    return std::any_of(screens.begin(), screens.end(), [&](const QScreen* screen) {
        return screen->availableGeometry().contains(geometry);
    });
}

}  // namespace whitted::ui
