// The editor's renderer thread (the restart loop of Qt's Mandelbrot example).
//
// The GUI calls request() with a snapshot of the scene on every edit; that bumps
// a generation number and returns at once. The thread renders the newest
// request progressively (core's renderer: preview, full resolution, more
// samples) and hands frames to the GUI through queued signals. A render asks
// "should I stop?" before every tile row, and the answer is yes as soon as a
// newer request exists, so a stale render ends within a row of work. Every frame
// carries its generation; the GUI drops frames older than its last request.
#pragma once

#include <QImage>
#include <QObject>
#include <QString>

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "renderer.h"
#include "scene.h"

namespace whitted::ui {

struct RenderFrame {
    quint64 generation = 0;
    QImage image;  // 8-bit sRGB at the scene's render size
    int pass = 0;  // 0-based pass the frame belongs to
    int passCount = 0;
    bool preview = false;         // the coarse first pass
    bool passComplete = false;    // every tile of `pass` is in the image
    bool renderComplete = false;  // the last pass is complete: nothing more will come
    int samples = 0;              // samples per pixel of the finished pixels (0 during the preview)
    double seconds = 0.0;         // since the render started
    double mraysPerSecond = 0.0;
    RenderSettings settings;  // what the frame is rendered with
    // Only in the complete frame: the linear image itself, shared rather than
    // copied (the trade-off dock measures errors on it), and its ray count.
    std::shared_ptr<const Image> linear;
    std::uint64_t rays = 0;
};

class RenderWorker : public QObject {
    Q_OBJECT
  public:
    explicit RenderWorker(QObject* parent = nullptr);
    ~RenderWorker() override;  // stops the current render and joins the thread

    // Starts rendering `scene` as soon as the current render has stopped;
    // returns the request's generation. Never blocks on the renderer.
    quint64 request(const Scene& scene);
    quint64 latestGeneration() const { return generation_.load(); }

    // How often frames are sent while a pass is in progress.
    static constexpr int kFrameIntervalMs = 40;

  signals:
    void frameReady(const whitted::ui::RenderFrame& frame);

  private:
    void run();
    void renderOne(const Scene& scene, quint64 generation);

    std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<Scene> pending_;  // guarded by mutex_
    bool quit_ = false;             // guarded by mutex_
    std::atomic<quint64> generation_{0};
    std::atomic<bool> quitting_{false};
    std::thread thread_;
};

}  // namespace whitted::ui

Q_DECLARE_METATYPE(whitted::ui::RenderFrame)
