// The editor's renderer thread (the restart loop of Qt's Mandelbrot example).
//
// The GUI calls request() with a snapshot of the scene on every edit
// (SceneDocument::snapshot(), shared, not copied); that
// returns at once with the request's generation (core/base/request_thread.h,
// the newest request wins). The thread renders the newest request progressively
// (core's renderer: preview, full resolution, more samples) and hands frames to
// the GUI through queued signals. A render asks "should I stop?" before every
// tile row, and the answer is yes as soon as a newer request exists, so a stale
// render ends within a row of work. Every frame carries its generation; the GUI
// drops frames older than its last request.
#pragma once

#include <QImage>
#include <QObject>
#include <QString>

#include <atomic>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>

#include "analysis/plan_memo.h"
#include "analysis/quality_target.h"
#include "base/request_thread.h"
#include "scene/scene.h"
#include "tracer/renderer.h"

namespace whitted::ui {

// The view never needs more pixels than a screen has: a scene larger than this
// on its long side is rendered for the view at a reduced size (same camera and
// aspect), so that opening a 16384x16384 scene neither allocates nor copies
// gigabytes per frame. Export renders the full size.
inline constexpr int kMaxViewSize = 2048;

// The scene as the view renders it: render size capped at kMaxViewSize.
Scene viewSized(Scene scene);

// The preview's block edge for the view's next render, from how long this
// render's preview took to trace (after the scene was prepared), `previewMs`,
// at block edge `block`, on a picture `width` pixels wide: twice as coarse
// while a preview takes longer than kPreviewBudgetMs, back to finer once the
// finer one (four times the rays) would fit with room. Never finer than
// kFinestPreviewBlock, nor coarser than a tile (32) or than kFewestPreviewBlocks
// across, where a preview no longer shows what moved. So the picture follows
// a drag on a large scene as closely as on a small one (bench_editor_gestures:
// 100,000 balls traced their 8-pixel preview in 10 to 25 ms of the 30 a move
// may take, their 16-pixel one in 3).
inline constexpr double kPreviewBudgetMs = 6.0;
inline constexpr int kFinestPreviewBlock = 8;
inline constexpr int kFewestPreviewBlocks = 32;
int nextPreviewBlock(int block, double previewMs, int width);
// `block` as a picture `width` pixels wide may have it: no coarser than
// kFewestPreviewBlocks across (the block kept from a wider scene's renders
// is made finer for a narrower one), never finer than kFinestPreviewBlock.
int previewBlockFor(int block, int width);

// What the view is asked to render: the scene, to its own samples and depth
// or, with a target, to that quality (document/quality_choice.h).
struct RenderRequest {
    std::shared_ptr<const Scene> scene;  // the document's snapshot, never copied to be read
    std::optional<QualityTarget> quality;
    std::optional<Whitted1980Sampling> whitted1980;  // instead of the scene's samples
    // The document's geometryRevision() of the scene: the same as the last
    // render's, the sphere tree is used as it is (no refit). 0: unknown.
    std::uint64_t geometryRevision = 0;
};

struct RenderFrame {
    quint64 generation = 0;
    // 8-bit sRGB at the scene's render size (viewSized()); a preview frame
    // holds one pixel per block of `block` x `block` render pixels.
    QImage image;
    int block = 1;
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
    // A render to a quality: what planQuality() chose (in every frame; its
    // depth is in `settings`) and, in the complete frame, what was reached.
    std::shared_ptr<const QualityPlan> qualityPlan;
    std::optional<AdaptiveOutcome> qualityReached;
    // Sampled as Whitted's 1980 paper does: how, and in the complete frame,
    // how deep each pixel was cut and the camera rays it took.
    std::optional<Whitted1980Sampling> whitted1980;
    std::shared_ptr<const SubdivisionLevels> subdivision;
    std::uint64_t cameraRays = 0;
};

class RenderWorker : public QObject {
    Q_OBJECT
  public:
    // A render to a quality takes its plan from `plans` (shared with the
    // Render tab's prediction), which must outlive the worker.
    explicit RenderWorker(PlanMemo& plans, QObject* parent = nullptr);
    ~RenderWorker() override = default;  // stops the current render and joins the thread

    // Starts rendering `scene` as soon as the current render has stopped;
    // returns the request's generation. Never blocks on the renderer. The
    // scene must pass validateScene(), as the document's always does; the
    // render does not check it again. `geometryRevision` as RenderRequest's.
    quint64 request(std::shared_ptr<const Scene> scene,
                    const std::optional<QualityTarget>& quality = std::nullopt,
                    const std::optional<Whitted1980Sampling>& whitted1980 = std::nullopt,
                    std::uint64_t geometryRevision = 0);
    quint64 latestGeneration() const { return requests_.latestTicket(); }
    // Drops the request still waiting, and its snapshot, for a caller about to
    // request again (RequestThread::dropWaiting()).
    void dropWaiting() { requests_.dropWaiting(); }

    // How often frames are sent while a pass is in progress.
    static constexpr int kFrameIntervalMs = 40;

    // How the renders so far got their sphere trees (built, refit, or kept as
    // they were). Read it between renders: the render thread updates it.
    int bvhBuilds() const { return bvhBuilds_.load(); }
    int bvhRefits() const { return bvhRefits_.load(); }
    int bvhReuses() const { return bvhReuses_.load(); }

  signals:
    // In the GUI thread (the thread this object lives in), every frame in order.
    void frameReady(const whitted::ui::RenderFrame& frame);
    // From the render thread: a frame is waiting in the outbox.
    void framePosted();

  private:
    void renderOne(RenderRequest requested, quint64 generation);
    // The render thread's frames pass through an outbox guarded by our own
    // mutex rather than inside Qt's queued signal: the hand-over is then a
    // synchronisation ThreadSanitizer can see (Qt's event queue is not
    // instrumented, and the stress test's frames looked like races).
    void post(RenderFrame frame);
    void deliver();  // GUI thread: takes the oldest frame and emits frameReady

    std::mutex outboxMutex_;
    std::deque<RenderFrame> outbox_;  // guarded by outboxMutex_

    PlanMemo& plans_;
    // Only the render thread touches the cache; the counts are copied out.
    BvhCache bvhCache_;
    int previewBlock_ = kFinestPreviewBlock;  // for the next render (nextPreviewBlock())
    std::atomic<int> bvhBuilds_{0}, bvhRefits_{0}, bvhReuses_{0};
    // Last, so that it stops and joins the render thread before the rest goes.
    RequestThread<RenderRequest> requests_;
};

}  // namespace whitted::ui

Q_DECLARE_METATYPE(whitted::ui::RenderFrame)
