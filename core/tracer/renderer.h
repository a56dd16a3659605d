// The progressive tile renderer: the image is cut into tiles that a pool of
// threads renders pass by pass, centre-out within each pass:
//   1. a coarse preview, one camera ray per block of previewBlock^2 pixels;
//   2. full resolution at one sample per pixel;
//   3. more samples, doubling each pass, up to samples_per_pixel.
// Every sample is a pure function of (pixel, sample index), and each pixel's
// samples are summed in index order, so the final image is bit-identical to a
// one-shot render whatever the thread count, tile size, tile order or pass split.
//
// Meant to be driven from the caller's own thread (the editor's worker, the
// CLI's main thread): render() blocks, uses the calling thread as one of its
// workers, and returns within one tile row of work once shouldStop says so.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "base/parallel_for.h"  // resolveThreadCount, for RenderOptions::threads
#include "image/image.h"
#include "scene/scene.h"
#include "tracer/adaptive_sampling.h"
#include "tracer/tracer.h"
#include "tracer/whitted1980_sampling.h"

namespace whitted {

struct RenderOptions {
    // Worker threads including the caller, which also prepare the scene and
    // build its tree; 0: every core this process may run on.
    int threads = 0;
    int tileSize = 32;        // tile edge in pixels (an adaptive render's: kAdaptiveTileEdge)
    bool progressive = true;  // false: a single pass of all samples, no preview
    // Pixels per preview block edge; 1 disables the preview. A block never
    // straddles two tiles: render() uses the largest divisor of tileSize not
    // above it.
    int previewBlock = 8;
    // The caller has checked the scene with validateScene() or validateEdit()
    // (the editor's document does, on every edit), so render() need not check
    // it again: at 100,000 spheres that second check was a tenth of an edit.
    bool sceneValidated = false;
    // Trees kept from the previous render, refit when only spheres moved
    // (bvh.h). The editor's render worker keeps one; one render at a time.
    BvhCache* bvhCache = nullptr;
    // Whether a render thread may make a light's buffer when its shadow rays
    // show that it pays (light_buffer.h). The image is the same either way:
    // off, for benchmarks and tests that compare.
    bool lightBuffers = true;
    // Only the pixels of these rectangles, which may not overlap, in one pass
    // of all their samples (no preview): each pixel's samples depend on the
    // pixel alone, so a region equals that part of the whole render, bit for
    // bit. The image keeps the render's full size, zero outside the regions;
    // its pages cost memory only where rendered. Empty: the whole image.
    // A farm task renders one; the speed probe, its tiles spread over the
    // picture, in one render (speed_probe.h).
    std::vector<PixelRect> regions{};
    // With regions and a limit on the largest error: the scene around the
    // regions as the whole render would show it. The estimates that look
    // past a tile's border (unseenLargest(), estimateNearbyLargest()) then
    // look past a region's, and a sample of the picture's tiles takes the
    // samples it takes in the whole (target_prediction.h). Not owned; null:
    // a region sees only itself.
    const AroundRegions* aroundRegions = nullptr;
    // Set: each tile is sampled until the picture's estimated error is under
    // these limits (adaptive_sampling.h), at most maxSamples per pixel; the
    // scene's samples_per_pixel is not used. Samples come from
    // progressiveSample(), passes double the samples of the tiles that need
    // them most, and the image is as deterministic as any other. With regions,
    // only their tiles, judged among themselves: a sample of the picture's
    // tiles whose samples and time stand for the whole's (target_prediction.h).
    std::optional<AdaptiveSampling> adaptive = std::nullopt;
    // Reflected and refracted rays whose path passes on less than this weight
    // are not traced, whatever the depth (PreparedScene::pruneBelow): for
    // renders to a quality and their planning, which go deep where light
    // trapped in lossless glass must be followed and a glass ball's faint
    // inner reflections need not (analysis/quality_target.h). 0: every ray
    // SPEC spawns.
    double pruneBelowWeight = 0.0;
    // Besides the picture, the picture as each of these shallower depths
    // would render it (ascending, each below the scene's max depth), from the
    // same rays (traceCameraRowAtDepths(); equal to those renders but for
    // rounding): RenderResult::atDepths. Planning compares depths so, one
    // render for several. Only for a fixed render without preview
    // (oneShotOptions()); std::invalid_argument otherwise.
    std::vector<int> alsoAtDepths{};
    // Set: Whitted's own adaptive antialiasing (whitted1980_sampling.h), in
    // one pass of the whole picture, instead of the scene's samples per pixel.
    // Not with `adaptive`, `regions` or `alsoAtDepths` (std::invalid_argument).
    std::optional<Whitted1980Sampling> whitted1980 = std::nullopt;
    // Called on the render's thread once the scene is prepared, before the
    // first tile.
    std::function<void()> onPrepared{};
    // Called on the render's thread once render() has read all it reads of the
    // scene it was given (the spheres prepared, before the tree's build or
    // refit): its owner may change or free it from then on. The editor's
    // worker lets go of its snapshot here, so that the next edit need not copy
    // the scene: at a million spheres a copy is 100 MB, and the tree's refit
    // after a large move took longer than the spheres' preparation.
    std::function<void()> onSceneRead{};
};

// For a render nobody watches (a file, a measurement): one pass of all the
// samples, no preview.
inline RenderOptions oneShotOptions() {
    RenderOptions options;
    options.progressive = false;
    return options;
}

enum class PassKind { Preview, Samples };

struct RenderProgress {
    int pass = 0;       // 0-based index of the current pass
    int passCount = 0;  // passes in this render
    PassKind kind = PassKind::Samples;
    int samples = 0;        // samples per pixel in the tile once this pass is done (0: preview)
    double fraction = 0.0;  // share of the whole render's work finished, in [0, 1]
    int tilesInPass = 0;    // tiles the pass reports, each exactly once
};

// The worker threads a render of these settings runs on with these options
// (RenderResult::threads): as many as asked, no more than its tiles.
int renderThreads(const RenderSettings& settings, const RenderOptions& options = {});

// The passes a render of these settings makes with these options (a fixed
// number of samples: not an adaptive render, whose passes depend on the picture).
int passCount(const RenderSettings& settings, const RenderOptions& options = {});

// A finished tile: the rectangle [x, x+width) x [y, y+height) of the render.
// `image` is the whole picture being refined, one pixel of it to each block of
// `block` x `block` render pixels: block 1 in a samples pass; in the preview,
// the preview block, so that the preview neither writes nor hands over a
// full-size image (at 1280x720 that traffic was most of its time). Only the
// tile's blocks changed (tileBlocks()), and they stay untouched until the
// callback returns, so the callback may copy them.
struct TileUpdate {
    const Image& image;
    int x, y, width, height;
    RenderProgress progress;
    int block = 1;
};

// The tile's pixels of TileUpdate::image: its rectangle divided by the block,
// rounded outward (the last block of a row or column may be partly outside the
// render).
PixelRect tileBlocks(const TileUpdate& tile);

// Writes the tile into a full-size image of the render, each block's pixel
// repeated over the block.
void copyTile(const TileUpdate& tile, Image& into);

// Called from the worker threads, possibly several at once: keep it short and
// thread-safe (copy the tile, post a message).
using TileCallback = std::function<void(const TileUpdate&)>;
// Asked before every tile row by every worker; must be thread-safe and cheap.
using StopPredicate = std::function<bool()>;

struct RenderResult {
    Image image;
    RayCounts rays;
    double seconds = 0.0;  // wall time of render(), preparation included
    // CPU time the worker threads spent on tiles, summed: what the tracing
    // cost, whatever else ran on the machine (thread_cpu_time.h).
    double tilesCpuSeconds = 0.0;
    int threads = 1;  // worker threads used
    // Samples per pixel in every pixel of `image`. 0: stopped before one
    // full-size pass was complete; `image` then holds the full-size tiles
    // finished, and zero elsewhere (the preview is only in the tile reports).
    // In an adaptive render: the fewest samples any tile got.
    int samples = 0;
    bool completed = false;                   // false when stopped early
    std::optional<AdaptiveOutcome> adaptive;  // set by adaptive renders
    std::vector<Image> atDepths;              // one for each of RenderOptions::alsoAtDepths
    // An adaptive render with a limit on the largest error: each rendered
    // pixel's estimate of it, in codes, at the samples its tile reached.
    PixelLargest pixelLargest;
    // A render with RenderOptions::whitted1980: how deep each pixel was cut.
    SubdivisionLevels subdivision;
    int lightBuffers = 0;  // lights whose buffer a render thread made
};

// Renders the scene with its render settings. Throws std::invalid_argument for a
// scene that validateScene() refuses or regions not inside the image or overlapping,
// std::runtime_error when WHITTED_KERNEL names a tracer kernel that is unknown or that this CPU
// cannot run.
RenderResult render(const Scene& scene, const RenderOptions& options = {},
                    const TileCallback& onTile = {}, const StopPredicate& shouldStop = {});

}  // namespace whitted
