#include "tracer/renderer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <numeric>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>

#include "base/elapsed.h"
#include "base/parallel_for.h"
#include "base/thread_cpu_time.h"
#include "scene/scene_io.h"
#include "tracer/kernel_dispatch.h"
#include "tracer/progress_share.h"
#include "tracer/render_tiles.h"
#include "tracer/whitted1980_render.h"

namespace whitted {

namespace {

template <typename T>
class TileRenderer {
  public:
    TileRenderer(const Scene& scene, const RenderOptions& options, const TileCallback& onTile,
                 const StopPredicate& shouldStop)
        : settings_(scene.render),
          s_(prepared(scene, options)),
          options_(options),
          onTile_(onTile),
          shouldStop_(shouldStop),
          block_(previewBlockOf(options)) {}

    RenderResult run() {
        tiles_ = renderTiles(settings_, options_);
        threads_ = threadsForTiles(options_, tiles_.size());
        RenderResult result = options_.adaptive ? runAdaptive() : runFixed();
        if (image_.rgb.empty()) startImage(PassKind::Samples);  // stopped in the preview
        result.threads = threads_;
        result.completed = !stopped_;
        result.rays = rays_;
        result.tilesCpuSeconds = tilesCpuSeconds_;
        result.image = std::move(image_);
        result.atDepths = std::move(atDepths_);
        for (const PreparedLight<T>& light : s_.lights)
            result.lightBuffers += light.buffer && light.buffer->ready();
        return result;
    }

  private:
    static PreparedScene<T> prepared(const Scene& scene, const RenderOptions& options) {
        PreparedScene<T> s =
            prepareScene<T>(scene, options.bvhCache, options.threads, options.onSceneRead);
        s.pruneBelow = T(options.pruneBelowWeight);
        if (options.adaptive) {
            s.samplesPerPixel = std::max(1, options.adaptive->maxSamples);
            s.openEndedSamples = true;
        }
        return s;
    }

    RenderResult runFixed() {
        const std::vector<RenderPass> passes = planPasses(settings_, options_);
        // Sums survive between passes only when a pixel gets its samples in
        // several passes. 24 bytes a pixel (6 GB at 16384x16384): taken from
        // zero pages, so nothing is written, and no time spent, before the
        // first tile; a page costs memory only once a tile of it is rendered.
        if (passes.back().firstSample > 0) sums_ = Sums(size_t(s_.width) * s_.height);
        double totalWork = 0.0;
        for (const RenderPass& p : passes) totalWork += p.work;
        progress_.expect(0.0, totalWork);
        std::vector<int> all(tiles_.size());
        std::iota(all.begin(), all.end(), 0);
        RenderResult result;
        for (size_t p = 0; p < passes.size() && !stopped_; ++p) {
            startImage(passes[p].kind);
            runPass(passes[p], int(p), int(passes.size()), all);
            if (!stopped_ && passes[p].kind == PassKind::Samples)
                result.samples = passes[p].lastSample;
        }
        return result;
    }

    // Each image only when its first pass starts: the full-size one (11 MB
    // at 1280x720) once the preview is out.
    void startImage(PassKind kind) {
        if (kind == PassKind::Preview)
            preview_ = Image((s_.width + block_ - 1) / block_, (s_.height + block_ - 1) / block_);
        else if (image_.rgb.empty()) {
            image_ = Image(s_.width, s_.height);
            for (std::size_t k = 0; k < options_.alsoAtDepths.size(); ++k)
                atDepths_.emplace_back(s_.width, s_.height);
        }
    }

    // The preview, two samples everywhere (or first the centres), then passes
    // that double the samples of the tiles tilesToRefine() picks, until it
    // picks none.
    RenderResult runAdaptive() {
        const AdaptiveSampling& limits = *options_.adaptive;
        startTileStates(limits);
        std::vector<RenderPass> passes = planPasses(settings_, options_);  // the preview, if any
        passes.resize(passes.front().kind == PassKind::Preview ? 1 : 0);
        std::vector<int> refine(tiles_.size());
        std::iota(refine.begin(), refine.end(), 0);
        int index = 0;
        if (!passes.empty()) {
            // The first samples, and the passes the guess expects after them.
            const double firstSamples =
                pixelsRendered(settings_, options_) * (limits.centresFirst ? 1 : 2);
            progress_.expect(
                0.0, passes.front().work + firstSamples * (1.0 + remainingPassesGuess(limits)));
            startImage(PassKind::Preview);
            runPass(passes.front(), 0, 1, refine);
            index = 1;
        }
        int samplesPasses = 0;
        if (limits.centresFirst) {
            const double pixels = pixelsRendered(settings_, options_);
            const RenderPass centres{PassKind::Samples, 0, 1, pixels, true};
            progress_.expect(workDone_,
                             workDone_ + centres.work * (1.0 + remainingPassesGuess(limits)));
            startImage(PassKind::Samples);
            runPass(centres, index, index + 1, refine);
            ++index, ++samplesPasses;
            refine = stopped_ ? std::vector<int>() : nextTiles(limits, refine);
        }
        RenderResult result;
        while (!refine.empty() && !stopped_) {
            // One pass for each sample count among the chosen tiles, fewest first.
            std::map<int, std::vector<int>> bySamples;
            for (int t : refine) bySamples[tileStates_[t].samples].push_back(t);
            for (const auto& [done, ids] : bySamples) {
                if (stopped_) break;
                // After the centres a tile starts the sequence over: a
                // centre is not one of its stratified samples.
                const int first = done == 1 ? 0 : done;
                const int next = std::min(limits.maxSamples, done <= 1 ? 2 : 2 * done);
                double pixels = 0.0;
                for (int t : ids) pixels += tileStates_[t].pixels;
                const RenderPass pass{PassKind::Samples, first, next, pixels * (next - first)};
                progress_.expect(workDone_, workDone_ + pass.work * remainingPassesGuess(limits));
                startImage(PassKind::Samples);
                // Not before: a render whose centres do needs no sums.
                if (sums_.empty()) sums_ = Sums(size_t(s_.width) * s_.height);
                runPass(pass, index, index + 1, ids);
                ++index, ++samplesPasses;
            }
            refine = nextTiles(limits, refine);
        }
        result.adaptive = adaptiveOutcome(tileStates_, limits, samplesPasses);
        result.pixelLargest = std::move(pixelLargest_);
        result.samples = stopped_ ? 0 : result.adaptive->fewestSamples;
        return result;
    }

    // Each tile's sampling state, and each pixel's largest error where the
    // limits hold it to one.
    void startTileStates(const AdaptiveSampling& limits) {
        tileStates_.resize(tiles_.size());
        for (size_t t = 0; t < tiles_.size(); ++t)
            tileStates_[t].pixels = tiles_[t].w * tiles_[t].h;
        if (limitsLargest(limits)) {
            pixelLargest_.width = s_.width, pixelLargest_.height = s_.height;
            pixelLargest_.codes.resize(std::size_t(s_.width) * s_.height);
        }
    }

    // `rendered`: the tiles the last pass rendered.
    std::vector<int> nextTiles(const AdaptiveSampling& limits, const std::vector<int>& rendered) {
        if (!pixelLargest_.codes.empty()) {
            std::vector<PixelRect> rects;
            for (const Tile& t : tiles_) rects.push_back({t.x, t.y, t.w, t.h});
            // Each tile writes only its own pixels' estimates: in parallel,
            // where a pass over a 640x480 picture takes 10 ms on one thread.
            parallelFor(rendered, threads_, [&](int t) {
                TileErrorEstimate& estimate = tileStates_[t].estimate;
                const double unseen =
                    unseenLargest(image_, rects[t], renderedAround(rects[t]),
                                  tileStates_[t].samples, pixelLargest_, aroundImage());
                estimate.largest = std::max(estimate.largest, unseen);
            });
            estimateNearbyLargest(tileStates_, rects, tileEdgeOf(options_), pixelLargest_,
                                  options_.aroundRegions);
        }
        return tilesToRefine(tileStates_, limits);
    }

    const Image* aroundImage() const {
        return options_.aroundRegions ? &options_.aroundRegions->image : nullptr;
    }

    // The pixels next to `tile` that this render renders: its region's.
    PixelRect renderedAround(const PixelRect& tile) const {
        for (const PixelRect& region : options_.regions)
            if (overlap(region, tile)) return region;
        return {0, 0, s_.width, s_.height};
    }

    // For the progress fraction: the passes left if each halves the error.
    double remainingPassesGuess(const AdaptiveSampling& limits) const {
        const double mse = estimatedPictureMse(tileStates_);
        if (mse <= 0.0 || limits.allowedMse <= 0.0) return 2.0;
        return 1.0 + std::max(0.0, std::log2(mse / limits.allowedMse));
    }
    // Slots for the lights' buffers (light_buffer.h) from the first pass with
    // enough camera samples for them: not for a preview, nor for a small render
    // of many spheres. A light that has its slot keeps it.
    void addLightBufferSlotsIfTheyMayPay(const RenderPass& pass, const std::vector<int>& ids) {
        if (!s_.useBvh || !options_.lightBuffers) return;
        double samples = 0;
        for (int id : ids) samples += double(tiles_[id].w) * tiles_[id].h;
        samples *= pass.lastSample - pass.firstSample;
        if (samples >= kLightBufferRaysPerSphere * s_.spheres.count()) addLightBufferSlots(s_);
    }

    bool stopRequested() {
        if (stopped_.load(std::memory_order_relaxed)) return true;
        if (shouldStop_ && shouldStop_()) stopped_ = true;
        return stopped_;
    }

    // Renders the tiles `ids` (indices into tiles_) through one pass.
    void runPass(const RenderPass& pass, int index, int count, const std::vector<int>& ids) {
        if (pass.kind == PassKind::Samples) addLightBufferSlotsIfTheyMayPay(pass, ids);
        std::atomic<size_t> next{0};
        const double workPerPixel = pass.kind == PassKind::Preview
                                        ? 1.0 / (double(block_) * block_)
                                        : double(pass.lastSample - pass.firstSample);
        auto worker = [&] {
            const double cpuAtStart = threadCpuSeconds();
            RayCounts counts;
            Row row;  // the worker's own
            for (;;) {
                if (stopRequested()) break;
                const size_t k = next.fetch_add(1);
                if (k >= ids.size()) break;
                const Tile& tile = tiles_[ids[k]];
                TileErrorEstimate* estimate = nullptr;
                if (!tileStates_.empty() && pass.kind == PassKind::Samples) {
                    estimate = &tileStates_[ids[k]].estimate;
                    *estimate = {};
                }
                if (!renderTile(pass, tile, row, counts, estimate)) break;
                if (estimate) tileStates_[ids[k]].samples = pass.lastSample;
                const double done = workDone_.fetch_add(workPerPixel * tile.w * tile.h) +
                                    workPerPixel * tile.w * tile.h;
                if (onTile_) {
                    RenderProgress progress{index,
                                            count,
                                            pass.kind,
                                            pass.kind == PassKind::Preview ? 0 : pass.lastSample,
                                            progress_.at(done),
                                            int(ids.size())};
                    const bool preview = pass.kind == PassKind::Preview;
                    onTile_(TileUpdate{preview ? preview_ : image_, tile.x, tile.y, tile.w, tile.h,
                                       progress, preview ? block_ : 1});
                }
            }
            std::lock_guard lock(raysMutex_);
            rays_ += counts;
            tilesCpuSeconds_ += threadCpuSeconds() - cpuAtStart;
        };
        std::vector<std::thread> helpers;
        for (int i = 1; i < std::min<int>(threads_, ids.size()); ++i) helpers.emplace_back(worker);
        worker();
        for (auto& h : helpers) h.join();
    }

    // A worker's buffers for one row of a tile, kept from tile to tile.
    struct Row {
        std::vector<Vec<T>> radiance;
        std::vector<glm::dvec3> sums;       // where the render keeps none
        std::vector<float> firstHalf;       // an adaptive pass's picture before it
        std::vector<Vec<T>> atDepths;       // renderRowAtDepths(): pixel by pixel, depth by depth
        std::vector<glm::dvec3> depthSums;  // the same, summed over the pass's samples
    };

    // The image is float whatever the precision: radiance beyond the largest
    // float (a light of intensity 1e300 in double, or sums that overflowed to
    // infinity) is stored as the largest float, never as infinity.
    template <typename V>
    static void storePixel(float* out, const V& radiance) {
        constexpr double kLargest = std::numeric_limits<float>::max();
        for (int c = 0; c < 3; ++c) out[c] = float(std::min(double(radiance[c]), kLargest));
    }

    // A sum of n samples over n. Dividing by a power of two and multiplying by
    // its inverse round the same exact quotient, so those passes (every one of
    // a progressive render but perhaps the last) multiply: a division per
    // channel was the largest cost of the tile loop after tracing.
    static void storeMean(float* out, const glm::dvec3& sum, int n) {
        if ((n & (n - 1)) == 0)
            storePixel(out, sum * (1.0 / double(n)));
        else
            storePixel(out, sum / double(n));
    }

    // Asks for the cache lines of `count` floats from `at` while the row is
    // traced: fetched only when the row was stored, the lines of a fresh
    // image held up the stores behind them.
    static void prefetchForWriting(const float* at, int count) {
        const char* first = reinterpret_cast<const char*>(at);
        for (int offset = 0; offset < count * int(sizeof(float)); offset += 64)
            __builtin_prefetch(first + offset, 1);
    }

    // A one-sample pass stores the samples as they come: what the sums would
    // hold, 0.0 + sample (which turns a -0.0 into +0.0), over 1.
    void storeSamples(const Vec<T>* radiance, int x, int y, int w) {
        float* out = image_.pixel(x, y);
        if constexpr (std::is_same_v<T, float>) {
            // The same values without the trip through double: x + 0.0f is
            // 0.0 + double(x) rounded back, in a loop the compiler vectorises
            // (the scalar conversions were a twentieth of a seed render).
            static_assert(sizeof(Vec<float>) == 3 * sizeof(float));
            const float* in = reinterpret_cast<const float*>(radiance);
            constexpr float kLargest = std::numeric_limits<float>::max();
            for (int i = 0; i < 3 * w; ++i) out[i] = std::min(in[i] + 0.0f, kLargest);
            return;
        }
        for (int i = 0; i < w; ++i) storePixel(out + 3 * i, 0.0 + glm::dvec3(radiance[i]));
    }

    // False when stopped part-way: the tile is then incomplete and not reported.
    // Out of line: the profiles of docs/design/performance.md collect from it.
    __attribute__((noinline)) bool renderTile(const RenderPass& pass, const Tile& tile, Row& row,
                                              RayCounts& counts, TileErrorEstimate* estimate) {
        if (pass.kind == PassKind::Preview) return renderPreviewTile(tile, counts);
        row.radiance.resize(std::size_t(tile.w) * kRowsAtOnce);
        row.sums.resize(tile.w);
        const bool oneSample =
            pass.centres || (pass.firstSample == 0 && pass.lastSample == 1 && sums_.empty());
        for (int y = tile.y; y < tile.y + tile.h;) {
            if (stopRequested()) return false;
            if (oneSample && options_.alsoAtDepths.empty()) {
                y += renderRowsOfOneSample(pass, tile, y, row, counts);
                continue;
            }
            prefetchForWriting(image_.pixel(tile.x, y), 3 * tile.w);
            if (!options_.alsoAtDepths.empty())
                renderRowAtDepths(pass, tile, y, row, counts);
            else
                renderRow(pass, tile, y, row, counts, estimate);
            ++y;
        }
        if (pass.centres && estimate)
            *estimate = centreSampleEstimate(image_, {tile.x, tile.y, tile.w, tile.h});
        return true;
    }

    // The rows a one-sample pass traces together: its packets are blocks of
    // pixels that tall (traceCameraRows()).
    static constexpr int kRowsAtOnce = 4;

    // Up to kRowsAtOnce rows of a one-sample pass from row y, stored as they
    // come. Returns the rows done.
    int renderRowsOfOneSample(const RenderPass& pass, const Tile& tile, int y, Row& row,
                              RayCounts& counts) {
        const int rows = std::min(kRowsAtOnce, tile.y + tile.h - y);
        for (int r = 0; r < rows; ++r) prefetchForWriting(image_.pixel(tile.x, y + r), 3 * tile.w);
        traceCameraRows(s_, y, rows, tile.x, tile.w, pass.centres ? kPixelCentre : 0,
                        row.radiance.data(), counts);
        for (int r = 0; r < rows; ++r)
            storeSamples(row.radiance.data() + std::size_t(r) * tile.w, tile.x, y + r, tile.w);
        return rows;
    }

    // A row of the pass's samples, and the same rays' radiance at each of
    // alsoAtDepths, summed in sample order as renderRow() sums them: the
    // pictures are those of renders at those depths but for rounding. A row
    // of pixels at a time: traceCameraBlock() has no depths to give.
    void renderRowAtDepths(const RenderPass& pass, const Tile& tile, int y, Row& row,
                           RayCounts& counts) {
        const std::vector<int>& depths = options_.alsoAtDepths;
        const int n = int(depths.size());
        const std::size_t w = std::size_t(tile.w);
        row.atDepths.resize(w * n);
        row.sums.assign(w, glm::dvec3(0.0));
        row.depthSums.assign(w * n, glm::dvec3(0.0));
        for (int sample = pass.firstSample; sample < pass.lastSample; ++sample) {
            traceCameraRowAtDepths(s_, y, tile.x, tile.w, sample, row.radiance.data(),
                                   depths.data(), n, row.atDepths.data(), counts);
            for (std::size_t i = 0; i < w; ++i) row.sums[i] += glm::dvec3(row.radiance[i]);
            for (std::size_t i = 0; i < w * n; ++i) row.depthSums[i] += glm::dvec3(row.atDepths[i]);
        }
        const int samples = pass.lastSample - pass.firstSample;
        float* out = image_.pixel(tile.x, y);
        for (std::size_t i = 0; i < w; ++i) storeMean(out + 3 * i, row.sums[i], samples);
        for (int k = 0; k < n; ++k) {
            float* at = atDepths_[k].pixel(tile.x, y);
            for (std::size_t i = 0; i < w; ++i)
                storeMean(at + 3 * i, row.depthSums[i * n + k], samples);
        }
    }

    // The samples a pixel of a tile's row traces at once, at most: a row of
    // 32 pixels then holds 96 KB of float radiance.
    static constexpr int kBlockSamples = 256;

    void renderRow(const RenderPass& pass, const Tile& tile, int y, Row& row, RayCounts& counts,
                   TileErrorEstimate* estimate) {
        const size_t at = size_t(y) * s_.width + tile.x;
        // In place where they survive the pass, not copied in and out.
        glm::dvec3* sums = sums_.empty() ? row.sums.data() : sums_.data() + at;
        if (pass.firstSample == 0) std::fill_n(sums, tile.w, glm::dvec3(0.0));
        // Pixel by pixel, in chunks of kBlockSamples: each pixel still sums
        // its samples in index order, as a one-shot render does.
        for (int n0 = pass.firstSample; n0 < pass.lastSample; n0 += kBlockSamples) {
            const int samples = std::min(kBlockSamples, pass.lastSample - n0);
            row.radiance.resize(std::size_t(tile.w) * samples);
            const Vec<T>* radiance = row.radiance.data();
            traceCameraBlock(s_, y, tile.x, tile.w, n0, samples, row.radiance.data(), counts);
            for (int i = 0; i < tile.w; ++i)
                for (int k = 0; k < samples; ++k) sums[i] += glm::dvec3(radiance[i * samples + k]);
            // An adaptive render's first pass, of two samples: its first
            // half, for the estimate, is the first sample.
            if (estimate && n0 == 0)
                for (int i = 0; i < tile.w; ++i)
                    storePixel(image_.pixel(tile.x + i, y), radiance[i * samples]);
        }
        const bool estimating = estimate && pass.lastSample > 1;
        float* out = image_.pixel(tile.x, y);
        // The picture after the tile's last pass is the first half.
        if (estimating) row.firstHalf.assign(out, out + 3 * tile.w);
        for (int i = 0; i < tile.w; ++i) storeMean(out + 3 * i, sums[i], pass.lastSample);
        if (!estimating) return;
        float* largest = pixelLargest_.codes.empty() ? nullptr : &pixelLargest_.at(tile.x, y);
        estimate->add(halvesEstimate(row.firstHalf.data(), out, tile.w, largest));
    }

    // One camera ray through the middle of each block, stored as the
    // preview's pixel of that block.
    bool renderPreviewTile(const Tile& tile, RayCounts& counts) {
        for (int by = tile.y; by < tile.y + tile.h; by += block_) {
            if (stopRequested()) return false;
            const int bh = std::min(block_, tile.y + tile.h - by);
            for (int bx = tile.x; bx < tile.x + tile.w; bx += block_) {
                const int bw = std::min(block_, tile.x + tile.w - bx);
                const Vec<T> c =
                    tracePixelSample(s_, bx + bw / 2, by + bh / 2, T(0.5), T(0.5), counts);
                storePixel(preview_.pixel(bx / block_, by / block_), c);
            }
        }
        return true;
    }

    // Copied before the preparation, after which the scene may be gone
    // (RenderOptions::onSceneRead).
    const RenderSettings settings_;
    PreparedScene<T> s_;  // gets its lights' buffer slots before the first pass that may pay
    const RenderOptions& options_;
    const TileCallback& onTile_;
    const StopPredicate& shouldStop_;
    const int block_;  // the preview's block edge
    Image preview_;    // one pixel per block
    Image image_;
    std::vector<Image> atDepths_;  // RenderOptions::alsoAtDepths
    using Sums = std::vector<glm::dvec3, LargeBufferAllocator<glm::dvec3>>;
    Sums sums_;
    std::atomic<bool> stopped_{false};
    std::atomic<double> workDone_{0.0};
    ProgressShare progress_;  // set between passes, read by the workers
    std::mutex raysMutex_;    // guards rays_ and tilesCpuSeconds_
    RayCounts rays_;
    double tilesCpuSeconds_ = 0.0;
    std::vector<Tile> tiles_;
    int threads_ = 1;
    std::vector<TileSamplingState> tileStates_;  // adaptive renders only
    PixelLargest pixelLargest_;  // adaptive renders with a limit on the largest error
};

template <typename T>
RenderResult renderWith(const Scene& scene, const RenderOptions& options,
                        const TileCallback& onTile, const StopPredicate& shouldStop) {
    const RenderSettings settings = scene.render;
    if (!options.whitted1980) {
        TileRenderer<T> renderer(scene, options, onTile, shouldStop);
        if (options.onPrepared) options.onPrepared();
        return renderer.run();
    }
    PreparedScene<T> s =
        prepareScene<T>(scene, options.bvhCache, options.threads, options.onSceneRead);
    s.pruneBelow = T(options.pruneBelowWeight);
    if (options.onPrepared) options.onPrepared();
    return renderWhitted1980(s, settings, options, onTile, shouldStop);
}

}  // namespace

int renderThreads(const RenderSettings& settings, const RenderOptions& options) {
    return threadsForTiles(options, renderTiles(settings, options).size());
}

int passCount(const RenderSettings& settings, const RenderOptions& options) {
    return int(planPasses(settings, options).size());
}

PixelRect tileBlocks(const TileUpdate& tile) {
    const int b = tile.block;
    const int x = tile.x / b, y = tile.y / b;
    return {x, y, (tile.x + tile.width + b - 1) / b - x, (tile.y + tile.height + b - 1) / b - y};
}

void copyTile(const TileUpdate& tile, Image& into) {
    for (int y = tile.y; y < tile.y + tile.height; ++y) {
        float* out = into.pixel(tile.x, y);
        if (tile.block == 1) {
            std::copy_n(tile.image.pixel(tile.x, y), 3 * tile.width, out);
            continue;
        }
        for (int x = tile.x; x < tile.x + tile.width; ++x, out += 3)
            std::copy_n(tile.image.pixel(x / tile.block, y / tile.block), 3, out);
    }
}

RenderResult render(const Scene& scene, const RenderOptions& options, const TileCallback& onTile,
                    const StopPredicate& shouldStop) {
    if (auto problem = options.sceneValidated ? std::nullopt : validateScene(scene))
        throw std::invalid_argument(problem->jsonPath + ": " + problem->reason);
    if (auto problem = optionsProblem(scene, options)) throw std::invalid_argument(*problem);
    // Here, not in a worker: a WHITTED_KERNEL this CPU cannot run throws to the caller.
    activeKernel();
    const auto start = std::chrono::steady_clock::now();
    RenderResult result = scene.render.precision == Precision::Double
                              ? renderWith<double>(scene, options, onTile, shouldStop)
                              : renderWith<float>(scene, options, onTile, shouldStop);
    result.seconds = secondsSince(start);
    return result;
}

}  // namespace whitted
