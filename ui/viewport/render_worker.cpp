#include "viewport/render_worker.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <shared_mutex>
#include <utility>

#include "viewport/image_convert.h"

namespace whitted::ui {

RenderWorker::RenderWorker(QObject* parent)
    : QObject(parent),
      requests_(
          RequestThread<Scene>::Policy::LatestWins,
          [this](Scene&& scene, quint64 generation) { renderOne(std::move(scene), generation); }) {
    qRegisterMetaType<whitted::ui::RenderFrame>();
    connect(this, &RenderWorker::framePosted, this, &RenderWorker::deliver, Qt::QueuedConnection);
}

void RenderWorker::post(RenderFrame frame) {
    {
        std::lock_guard lock(outboxMutex_);
        outbox_.push_back(std::move(frame));
    }
    emit framePosted();  // one event per frame: deliver() takes one each time
}

void RenderWorker::deliver() {
    RenderFrame frame;
    {
        std::lock_guard lock(outboxMutex_);
        if (outbox_.empty()) return;
        frame = std::move(outbox_.front());
        outbox_.pop_front();
    }
    emit frameReady(frame);
}

quint64 RenderWorker::request(const Scene& scene) {
    return requests_.request(scene);
}

Scene viewSized(Scene scene) {
    const int longest = std::max(scene.render.width, scene.render.height);
    if (longest > kMaxViewSize) {
        auto scaled = [&](int size) {
            return std::max(1, int(std::lround(double(size) * kMaxViewSize / longest)));
        };
        scene.render.width = scaled(scene.render.width);
        scene.render.height = scaled(scene.render.height);
    }
    return scene;
}

void RenderWorker::renderOne(Scene requested, quint64 generation) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    const Scene scene = viewSized(std::move(requested));
    const int width = scene.render.width, height = scene.render.height;
    // The preview's pixels, one per block, then the full-size picture, made
    // from them when the first full-resolution tile arrives: the preview
    // frame is out before 3.7 MB of pixels are written at 1280x720.
    QImage preview, display;
    int previewBlock = 1;
    std::once_flag previewMade, displayMade;

    // Tile callbacks arrive from the renderer's threads at once. Tiles are disjoint,
    // so they convert in parallel under a shared lock; copying a frame out takes
    // it exclusively (about a millisecond every kFrameIntervalMs), so no frame
    // holds half a tile. The bookkeeping has a mutex of its own.
    std::shared_mutex imageLock;
    std::mutex frameMutex;
    int currentPass = -1, tilesDone = 0;  // tiles of currentPass converted so far
    int samplesDone = 0;                  // samples in every pixel: those of the last complete pass
    auto lastSent = start;

    auto makeFrame = [&](const RenderProgress& p, bool passComplete) {
        RenderFrame frame;
        frame.generation = generation;
        frame.pass = p.pass;
        frame.passCount = p.passCount;
        frame.preview = p.kind == PassKind::Preview;
        frame.passComplete = passComplete;
        frame.samples = samplesDone;
        frame.settings = scene.render;
        frame.seconds = std::chrono::duration<double>(Clock::now() - start).count();
        return frame;
    };

    const auto shouldStop = [&] { return requests_.stale(generation); };
    RenderProgress lastProgress;
    const auto onTile = [&](const TileUpdate& t) {
        const bool isPreview = t.progress.kind == PassKind::Preview;
        if (isPreview) {
            std::call_once(previewMade, [&] {
                preview = QImage(t.image.width, t.image.height, QImage::Format_RGB32);
                preview.fill(Qt::black);
                previewBlock = t.block;
            });
        } else {
            std::call_once(displayMade, [&] {
                display = preview.isNull() ? blackImage(width, height)
                                           : blocksEnlarged(preview, previewBlock, width, height);
            });
        }
        {
            std::shared_lock shared(imageLock);
            const PixelRect r = tileBlocks(t);
            convertRegion(t.image, isPreview ? preview : display, r.x, r.y, r.width, r.height);
        }
        std::lock_guard lock(frameMutex);
        lastProgress = t.progress;
        // Counted after the conversion, so a complete pass is complete in `display`.
        if (t.progress.pass != currentPass) {
            currentPass = t.progress.pass;
            tilesDone = 0;
        }
        const bool passComplete = ++tilesDone == t.progress.tilesInPass;
        if (passComplete && t.progress.kind == PassKind::Samples) samplesDone = t.progress.samples;
        const bool lastPass = t.progress.pass + 1 == t.progress.passCount;
        if ((passComplete && lastPass) || shouldStop()) return;  // the final frame follows below
        if (passComplete || Clock::now() - lastSent > std::chrono::milliseconds(kFrameIntervalMs)) {
            RenderFrame frame = makeFrame(t.progress, passComplete);
            {
                std::unique_lock exclusive(imageLock);
                frame.image = (isPreview ? preview : display).copy();
            }
            if (isPreview) frame.block = previewBlock;
            post(std::move(frame));
            lastSent = Clock::now();
        }
    };
    RenderOptions options;
    options.sceneValidated = true;  // request() asks for a valid scene
    options.bvhCache = &bvhCache_;
    RenderResult result = render(scene, options, onTile, shouldStop);
    bvhBuilds_ = bvhCache_.builds;
    bvhRefits_ = bvhCache_.refits;
    if (!result.completed) return;  // superseded: a newer request is waiting

    RenderFrame frame = makeFrame(lastProgress, true);
    frame.image = display;  // no tile writes it any more
    frame.renderComplete = true;
    frame.samples = result.samples;
    frame.seconds = result.seconds;
    frame.mraysPerSecond = result.seconds > 0 ? result.rays.total() / result.seconds / 1e6 : 0.0;
    frame.rays = result.rays.total();
    frame.linear = std::make_shared<const Image>(std::move(result.image));
    post(std::move(frame));
}

}  // namespace whitted::ui
