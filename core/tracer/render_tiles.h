// The tiles a render cuts the picture into, the order it renders them in,
// and its passes; and what in RenderOptions a render cannot do.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "tracer/renderer.h"

namespace whitted {

struct Tile {
    int x, y, w, h;
};

// Tiles of `size` pixels, centre-out: the middle of the picture, where people
// look, arrives first.
std::vector<Tile> spiralTiles(int width, int height, int size);

struct RenderPass {
    PassKind kind;
    int firstSample, lastSample;  // samples [first, last) of every pixel
    double work;                  // relative cost, for the progress fraction
    bool centres = false;         // one sample at each pixel's centre (kPixelCentre)
};

// The tile edge: an adaptive render's own (adaptive_sampling.h), else as asked.
int tileEdgeOf(const RenderOptions& o);

// The preview's block edge: a divisor of the tile edge, so that tiles hold
// whole blocks and no block is traced twice.
int previewBlockOf(const RenderOptions& o);

// The tiles a render works through, in the order it takes them.
std::vector<Tile> renderTiles(const RenderSettings& r, const RenderOptions& o);

// The threads a render of `tiles` tiles runs on: as asked, no more than its tiles.
int threadsForTiles(const RenderOptions& o, std::size_t tiles);

// The pixels a render traces: its regions', or the whole picture's.
double pixelsRendered(const RenderSettings& r, const RenderOptions& o);

// The passes of a render: one, or for a progressive render of the whole
// picture the preview (if any), then samples doubling from one pass to the next.
std::vector<RenderPass> planPasses(const RenderSettings& r, const RenderOptions& o);

// Why `options` cannot render `scene`'s picture, in words; nothing if they
// can (the scene's own rules are validateScene's).
std::optional<std::string> optionsProblem(const Scene& scene, const RenderOptions& options);

}  // namespace whitted
