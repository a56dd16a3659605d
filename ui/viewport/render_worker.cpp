#include "viewport/render_worker.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <mutex>
#include <shared_mutex>
#include <utility>

#include "base/elapsed.h"
#include "viewport/image_convert.h"

namespace whitted::ui {

RenderWorker::RenderWorker(PlanMemo& plans, QObject* parent)
    : QObject(parent),
      plans_(plans),
      requests_(RequestThread<RenderRequest>::Policy::LatestWins,
                [this](RenderRequest&& request, quint64 generation) {
                    renderOne(std::move(request), generation);
                }) {
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

quint64 RenderWorker::request(std::shared_ptr<const Scene> scene,
                              const std::optional<QualityTarget>& quality,
                              const std::optional<Whitted1980Sampling>& whitted1980,
                              std::uint64_t geometryRevision) {
    return requests_.request(
        RenderRequest{std::move(scene), quality, whitted1980, geometryRevision});
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

int previewBlockFor(int block, int width) {
    while (block > kFinestPreviewBlock && width / block < kFewestPreviewBlocks) block /= 2;
    return std::max(block, kFinestPreviewBlock);
}

int nextPreviewBlock(int block, double previewMs, int width) {
    constexpr int kTile = 32;
    const int coarser = 2 * block;
    if (previewMs > kPreviewBudgetMs)
        return coarser <= kTile && width / coarser >= kFewestPreviewBlocks ? coarser : block;
    if (block > kFinestPreviewBlock && 4 * previewMs < 0.75 * kPreviewBudgetMs) return block / 2;
    return block;
}

namespace {

using Clock = std::chrono::steady_clock;

// Turns one render's tiles into the view's frames. The preview's pixels, one
// per block, then the full-size picture, made from them when the first
// full-resolution tile arrives: the preview frame is out before 3.7 MB of
// pixels are written at 1280x720.
//
// Tiles arrive from the renderer's threads at once. Tiles are disjoint, so
// they convert in parallel under a shared lock; copying a frame out takes it
// exclusively (about a millisecond every kFrameIntervalMs), so no frame holds
// half a tile. The bookkeeping has a mutex of its own, held while a frame is
// posted, so frames go out in the order they were made.
class FrameAssembler {
  public:
    FrameAssembler(const Scene& scene, std::shared_ptr<const QualityPlan> plan,
                   std::optional<Whitted1980Sampling> whitted1980, quint64 generation,
                   std::function<bool()> stopping, std::function<void(RenderFrame)> post)
        : settings_(scene.render),
          plan_(std::move(plan)),
          whitted1980_(whitted1980),
          generation_(generation),
          stopping_(std::move(stopping)),
          post_(std::move(post)),
          start_(Clock::now()),
          lastSent_(start_) {}

    void addTile(const TileUpdate& t) {
        const bool isPreview = t.progress.kind == PassKind::Preview;
        convert(t, isPreview);
        std::lock_guard lock(frameMutex_);
        lastProgress_ = t.progress;
        // Counted after the conversion, so a complete pass is complete in `display_`.
        if (t.progress.pass != currentPass_) {
            currentPass_ = t.progress.pass;
            tilesDone_ = 0;
        }
        const bool passComplete = ++tilesDone_ == t.progress.tilesInPass;
        if (passComplete && t.progress.kind == PassKind::Samples) samplesDone_ = t.progress.samples;
        if (passComplete && isPreview) previewDone_ = Clock::now();
        // A render to a plan counts its passes as it goes (each decides whether
        // another follows), so none is known to be the last: each complete one
        // is shown, and finalFrame() follows the one that was.
        const bool lastPass = !plan_ && t.progress.pass + 1 == t.progress.passCount;
        if ((passComplete && lastPass) || stopping_()) return;  // finalFrame() follows
        if (passComplete ||
            Clock::now() - lastSent_ > std::chrono::milliseconds(RenderWorker::kFrameIntervalMs)) {
            RenderFrame frame = makeFrame(t.progress, passComplete);
            {
                std::unique_lock exclusive(imageLock_);
                frame.image = (isPreview ? preview_ : display_).copy();
            }
            if (isPreview) frame.block = previewBlock_;
            post_(std::move(frame));
            lastSent_ = Clock::now();
        }
    }

    // When the preview's last tile was converted; nothing when it was not.
    // Read once render() has returned.
    std::optional<Clock::time_point> previewDone() const { return previewDone_; }

    // The complete render's frame, with its linear image and figures.
    RenderFrame finalFrame(RenderResult result) {
        RenderFrame frame = makeFrame(lastProgress_, true);
        frame.image = display_;  // no tile writes it any more
        frame.renderComplete = true;
        frame.samples = result.samples;
        frame.seconds = result.seconds;
        frame.mraysPerSecond =
            result.seconds > 0 ? result.rays.total() / result.seconds / 1e6 : 0.0;
        frame.rays = result.rays.total();
        frame.linear = std::make_shared<const Image>(std::move(result.image));
        frame.qualityReached = result.adaptive;
        frame.cameraRays = result.rays.camera;
        if (!result.subdivision.levels.empty())
            frame.subdivision =
                std::make_shared<const SubdivisionLevels>(std::move(result.subdivision));
        return frame;
    }

  private:
    // The tile's pixels into the preview or the full-size picture.
    void convert(const TileUpdate& t, bool isPreview) {
        if (isPreview) {
            std::call_once(previewMade_, [&] {
                preview_ = QImage(t.image.width, t.image.height, QImage::Format_RGB32);
                preview_.fill(Qt::black);
                previewBlock_ = t.block;
            });
        } else {
            std::call_once(displayMade_, [&] {
                const int width = settings_.width, height = settings_.height;
                display_ = preview_.isNull()
                               ? blackImage(width, height)
                               : blocksEnlarged(preview_, previewBlock_, width, height);
            });
        }
        std::shared_lock shared(imageLock_);
        const PixelRect r = tileBlocks(t);
        convertRegion(t.image, isPreview ? preview_ : display_, r.x, r.y, r.width, r.height);
    }

    RenderFrame makeFrame(const RenderProgress& p, bool passComplete) const {
        RenderFrame frame;
        frame.generation = generation_;
        frame.pass = p.pass;
        frame.passCount = p.passCount;
        frame.preview = p.kind == PassKind::Preview;
        frame.passComplete = passComplete;
        frame.samples = samplesDone_;
        frame.settings = settings_;
        frame.qualityPlan = plan_;
        frame.whitted1980 = whitted1980_;
        frame.seconds = secondsSince(start_);
        return frame;
    }

    const RenderSettings settings_;
    const std::shared_ptr<const QualityPlan> plan_;
    const std::optional<Whitted1980Sampling> whitted1980_;
    const quint64 generation_;
    const std::function<bool()> stopping_;
    const std::function<void(RenderFrame)> post_;
    const Clock::time_point start_;

    QImage preview_, display_;
    int previewBlock_ = 1;
    std::once_flag previewMade_, displayMade_;
    std::shared_mutex imageLock_;

    std::mutex frameMutex_;                 // guards what follows
    int currentPass_ = -1, tilesDone_ = 0;  // tiles of currentPass_ converted so far
    int samplesDone_ = 0;  // samples in every pixel: those of the last complete pass
    Clock::time_point lastSent_;
    RenderProgress lastProgress_;
    std::optional<Clock::time_point> previewDone_;
};

}  // namespace

void RenderWorker::renderOne(RenderRequest requested, quint64 generation) {
    // Read where the document left it, and copied only to be changed: to the
    // view's size, or to a plan's depth.
    std::shared_ptr<const Scene> shared = std::move(requested.scene);
    if (std::max(shared->render.width, shared->render.height) > kMaxViewSize)
        shared = std::make_shared<const Scene>(viewSized(*shared));
    const auto shouldStop = [&] { return requests_.stale(generation); };
    RenderOptions options;
    options.sceneValidated = true;  // request() asks for a valid scene
    options.bvhCache = &bvhCache_;
    bvhCache_.geometryRevision = requested.geometryRevision;
    std::shared_ptr<const QualityPlan> plan;
    if (requested.quality) {
        // Chosen for the picture the view shows: its size, the scene's precision.
        plan = plans_.plan(*shared, *requested.quality, kDefaultMaxSamples, shouldStop);
        if (plan->stopped || shouldStop()) return;
        auto planned = std::make_shared<Scene>(*shared);
        applyPlan(*plan, *planned, options);
        shared = std::move(planned);
    }
    options.whitted1980 = requested.whitted1980;
    // Once its spheres are prepared, the render reads nothing of the scene:
    // let go of the snapshot, so that an edit made while it renders, or while
    // it refits the tree, writes in place instead of copying the scene
    // (bench_big_scene's edits back to back at a million spheres, 100 MB a copy).
    options.onSceneRead = [&] { shared.reset(); };
    std::optional<Clock::time_point> prepared;
    options.onPrepared = [&] { prepared = Clock::now(); };
    const Scene& scene = *shared;
    const int width = scene.render.width;  // `scene` may be gone once prepared
    options.previewBlock = previewBlock_ = previewBlockFor(previewBlock_, width);
    FrameAssembler frames(scene, plan, options.whitted1980, generation, shouldStop,
                          [this](RenderFrame frame) { post(std::move(frame)); });
    RenderResult result = render(
        scene, options, [&](const TileUpdate& t) { frames.addTile(t); }, shouldStop);
    bvhBuilds_ = bvhCache_.builds;
    bvhRefits_ = bvhCache_.refits;
    bvhReuses_ = bvhCache_.reuses;
    if (prepared && frames.previewDone())
        previewBlock_ = nextPreviewBlock(
            previewBlock_,
            std::chrono::duration<double, std::milli>(*frames.previewDone() - *prepared).count(),
            width);
    if (!result.completed) return;  // superseded: a newer request is waiting
    post(frames.finalFrame(std::move(result)));
}

}  // namespace whitted::ui
