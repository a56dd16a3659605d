// Opening a scene file without freezing the editor: a file of a million
// spheres takes seconds to read, so core's loadScene runs on a worker thread
// while the event loop keeps the window painting, and a window-modal progress
// dialog appears once the reading has taken 300 ms.
#pragma once

#include <QString>
#include <QWidget>

#include <functional>
#include <optional>

#include "scene/scene.h"

namespace whitted::ui {

// Called in the GUI thread as the file is read: bytes read and the file's size.
using LoadProgressShown = std::function<void(qint64 done, qint64 total)>;

// Returns the scene, or nothing with core's message in `error`.
std::optional<Scene> loadSceneShowingProgress(QWidget* parent, const QString& path, QString* error,
                                              const LoadProgressShown& onProgress = {});

}  // namespace whitted::ui
