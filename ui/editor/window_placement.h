// Where the main window opens: on a first start as large as is comfortable on
// the screen it opens on, later where the user left it, if a screen can show it.
#pragma once

#include <QRect>
#include <QSize>

namespace whitted::ui {

// The first start's size: 1400 x 860, shrunk to nine tenths of the screen's
// available area where that is smaller (a 1366 x 768 laptop), so that the
// docks, the status bar and the list's buttons are all on the screen.
QSize firstWindowSize(QSize available);

// Whether some screen's available area holds `geometry` (a window's, as saved)
// whole: a window remembered on a larger or a disconnected screen does not fit.
bool someScreenShows(const QRect& geometry);

}  // namespace whitted::ui
