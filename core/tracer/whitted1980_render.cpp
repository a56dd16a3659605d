#include "tracer/whitted1980_render.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <mutex>
#include <numeric>
#include <utility>

#include "base/parallel_for.h"
#include "base/thread_cpu_time.h"
#include "image/srgb.h"
#include "tracer/render_tiles.h"

namespace whitted {
namespace {

// A traced corner: its radiance, and its channels in 8-bit codes, which
// every cell that shares it compares: encoded once a corner, from the table
// (srgbEncodeFast: within a four-hundredth of a code; std::pow took a
// tenth of the render).
template <typename T>
struct Corner {
    Vec<T> radiance{0};
    std::array<float, 3> codes{};
};

template <typename T>
Corner<T> cornerOf(const Vec<T>& radiance) {
    return {radiance,
            {255.0f * srgbEncodeFast(float(radiance.r)), 255.0f * srgbEncodeFast(float(radiance.g)),
             255.0f * srgbEncodeFast(float(radiance.b))}};
}

template <typename T>
class Whitted1980Renderer {
  public:
    Whitted1980Renderer(const PreparedScene<T>& s, const RenderSettings& settings,
                        const RenderOptions& options, const TileCallback& onTile,
                        const StopPredicate& shouldStop)
        : s_(s),
          options_(options),
          onTile_(onTile),
          shouldStop_(shouldStop),
          width_(settings.width),
          height_(settings.height),
          levels_(options.whitted1980->maxLevels),
          unit_(std::int64_t(1) << levels_),
          threshold_(options.whitted1980->threshold),
          image_(width_, height_),
          subdivision_{width_, height_, std::vector<std::uint8_t>(std::size_t(width_) * height_)} {}

    RenderResult run() {
        const std::vector<Tile> tiles = spiralTiles(width_, height_, tileEdge());
        threads_ = std::max(1, std::min(resolveThreadCount(options_.threads), int(tiles.size())));
        traceCorners();
        std::vector<int> order(tiles.size());
        std::iota(order.begin(), order.end(), 0);
        std::atomic<int> done{0};
        parallelFor(order, threads_, [&](int t) {
            if (stopped_ || (shouldStop_ && shouldStop_())) {
                stopped_ = true;
                return;
            }
            const double cpuAtStart = threadCpuSeconds();
            RayCounts counts;
            renderTile(tiles[t], counts);
            addWork(counts, threadCpuSeconds() - cpuAtStart);
            if (onTile_) {
                const int finished = ++done;
                RenderProgress progress{0,
                                        1,
                                        PassKind::Samples,
                                        1,
                                        double(finished) / double(tiles.size()),
                                        int(tiles.size())};
                onTile_(TileUpdate{image_, tiles[t].x, tiles[t].y, tiles[t].w, tiles[t].h, progress,
                                   1});
            }
        });
        RenderResult result;
        result.threads = threads_;
        result.completed = !stopped_;
        result.samples = stopped_ ? 0 : 1;
        result.rays = rays_;
        result.tilesCpuSeconds = cpuSeconds_;
        result.image = std::move(image_);
        result.subdivision = std::move(subdivision_);
        return result;
    }

  private:
    // Tiles small enough that a tile's lattice stays under 2^18 points (7 MB)
    // however deep the cuts may go: at 6 cuts, 8 pixels a side.
    int tileEdge() const { return std::clamp(int(512 / unit_), 1, std::max(1, options_.tileSize)); }

    CameraSample<T> sampleAt(std::int64_t x, std::int64_t y) const {
        const std::int64_t mask = unit_ - 1;
        return {int(x >> levels_), int(y >> levels_), T(x & mask) / T(unit_),
                T(y & mask) / T(unit_)};
    }

    // The pixels' corners, (width + 1) x (height + 1), each traced once for
    // the four pixels that share it.
    void traceCorners() {
        const int columns = width_ + 1;
        corners_.resize(std::size_t(columns) * (height_ + 1));
        std::vector<int> rows(height_ + 1);
        std::iota(rows.begin(), rows.end(), 0);
        parallelFor(rows, threads_, [&](int j) {
            if (stopped_ || (shouldStop_ && shouldStop_())) {
                stopped_ = true;
                return;
            }
            const double cpuAtStart = threadCpuSeconds();
            std::vector<CameraSample<T>> samples(columns);
            for (int i = 0; i < columns; ++i) samples[i] = sampleAt(i * unit_, j * unit_);
            std::vector<Vec<T>> radiance(columns);
            RayCounts counts;
            traceCameraSamples(s_, samples.data(), columns, radiance.data(), counts);
            for (int i = 0; i < columns; ++i)
                corners_[std::size_t(j) * columns + i] = cornerOf(radiance[i]);
            addWork(counts, threadCpuSeconds() - cpuAtStart);
        });
    }

    // What one tile has traced below the pixels' corners: a dense grid of its
    // lattice (a hash of the points traced took half again as long), kept from
    // tile to tile by each thread, so that only its flags are cleared.
    struct TilePoints {
        std::int64_t x0 = 0, y0 = 0;  // the tile's first lattice point
        std::size_t columns = 0;      // lattice points across the tile
        std::vector<Corner<T>> corner;
        std::vector<std::uint8_t> known;
        std::vector<CameraSample<T>> wanted;
        std::vector<std::size_t> wantedAt;  // where each wanted corner goes in `corner`
        std::size_t index(std::int64_t x, std::int64_t y) const {
            return std::size_t(y - y0) * columns + std::size_t(x - x0);
        }
    };

    void startTile(TilePoints& points, const Tile& tile) const {
        points.x0 = tile.x * unit_;
        points.y0 = tile.y * unit_;
        points.columns = std::size_t(tile.w * unit_ + 1);
        const std::size_t size = points.columns * std::size_t(tile.h * unit_ + 1);
        if (points.corner.size() < size) points.corner.resize(size);
        points.known.assign(size, 0);
    }

    const Corner<T>& at(const TilePoints& points, std::int64_t x, std::int64_t y) const {
        if (x % unit_ == 0 && y % unit_ == 0)
            return corners_[std::size_t(y / unit_) * (width_ + 1) + std::size_t(x / unit_)];
        return points.corner[points.index(x, y)];
    }

    // Whether a cell's corners differ by more than the threshold on screen.
    bool differ(const Corner<T>& a, const Corner<T>& b, const Corner<T>& c,
                const Corner<T>& d) const {
        for (int k = 0; k < 3; ++k) {
            const float low = std::min({a.codes[k], b.codes[k], c.codes[k], d.codes[k]});
            const float high = std::max({a.codes[k], b.codes[k], c.codes[k], d.codes[k]});
            if (double(high - low) > threshold_) return true;
        }
        return false;
    }

    struct Cell {
        std::int64_t x, y, size;  // lattice units
        std::size_t pixel;        // index in subdivision_
    };

    bool cut(const TilePoints& points, const Cell& c) const {
        return differ(at(points, c.x, c.y), at(points, c.x + c.size, c.y),
                      at(points, c.x, c.y + c.size), at(points, c.x + c.size, c.y + c.size));
    }

    void want(TilePoints& points, std::int64_t x, std::int64_t y) const {
        const std::size_t at = points.index(x, y);
        if (std::exchange(points.known[at], 1)) return;  // shared with a neighbour
        points.wanted.push_back(sampleAt(x, y));
        points.wantedAt.push_back(at);
    }

    // Level by level over the whole tile, so that each level's new corners
    // are traced together, several rays a packet.
    void renderTile(const Tile& tile, RayCounts& counts) {
        thread_local TilePoints points;
        startTile(points, tile);
        std::vector<Cell> cells, next;
        for (int y = tile.y; y < tile.y + tile.h; ++y)
            for (int x = tile.x; x < tile.x + tile.w; ++x)
                cells.push_back({x * unit_, y * unit_, unit_, std::size_t(y) * width_ + x});
        for (int level = 1; level <= levels_ && !cells.empty(); ++level, std::swap(cells, next)) {
            next.clear();
            for (const Cell& c : cells) {
                if (!cut(points, c)) continue;
                subdivision_.levels[c.pixel] = std::uint8_t(level);
                const std::int64_t h = c.size / 2;
                want(points, c.x + h, c.y);
                want(points, c.x, c.y + h);
                want(points, c.x + h, c.y + h);
                want(points, c.x + c.size, c.y + h);
                want(points, c.x + h, c.y + c.size);
                for (const auto& [dx, dy] : {std::pair{0, 0}, {1, 0}, {0, 1}, {1, 1}})
                    next.push_back({c.x + dx * h, c.y + dy * h, h, c.pixel});
            }
            if (points.wanted.empty()) continue;
            std::vector<Vec<T>> radiance(points.wanted.size());
            traceCameraSamples(s_, points.wanted.data(), int(points.wanted.size()), radiance.data(),
                               counts);
            for (std::size_t k = 0; k < radiance.size(); ++k)
                points.corner[points.wantedAt[k]] = cornerOf(radiance[k]);
            points.wanted.clear();
            points.wantedAt.clear();
        }
        for (int y = tile.y; y < tile.y + tile.h; ++y)
            for (int x = tile.x; x < tile.x + tile.w; ++x) {
                const Vec<T> value = cellValue(points, {x * unit_, y * unit_, unit_, 0}, 0);
                float* out = image_.pixel(x, y);
                for (int k = 0; k < 3; ++k) out[k] = float(value[k]);
            }
    }

    // The mean of the cell's corners, or of its quarters' where it was cut:
    // the same decisions as renderTile's, from the same corners.
    Vec<T> cellValue(const TilePoints& points, const Cell& c, int level) const {
        if (level < levels_ && cut(points, c)) {
            const std::int64_t h = c.size / 2;
            return (cellValue(points, {c.x, c.y, h, 0}, level + 1) +
                    cellValue(points, {c.x + h, c.y, h, 0}, level + 1) +
                    cellValue(points, {c.x, c.y + h, h, 0}, level + 1) +
                    cellValue(points, {c.x + h, c.y + h, h, 0}, level + 1)) *
                   T(0.25);
        }
        return (at(points, c.x, c.y).radiance + at(points, c.x + c.size, c.y).radiance +
                at(points, c.x, c.y + c.size).radiance +
                at(points, c.x + c.size, c.y + c.size).radiance) *
               T(0.25);
    }

    void addWork(const RayCounts& counts, double cpuSeconds) {
        std::lock_guard lock(mutex_);
        rays_ += counts;
        cpuSeconds_ += cpuSeconds;
    }

    const PreparedScene<T>& s_;
    const RenderOptions& options_;
    const TileCallback& onTile_;
    const StopPredicate& shouldStop_;
    const int width_, height_, levels_;
    // Steps of the lattice along a pixel's edge, 2^maxLevels: every corner a
    // cut can make has whole coordinates on it.
    const std::int64_t unit_;
    const double threshold_;
    int threads_ = 1;
    std::vector<Corner<T>> corners_;
    Image image_;
    SubdivisionLevels subdivision_;
    std::atomic<bool> stopped_{false};
    std::mutex mutex_;  // guards rays_ and cpuSeconds_
    RayCounts rays_;
    double cpuSeconds_ = 0.0;
};

}  // namespace

template <typename T>
RenderResult renderWhitted1980(const PreparedScene<T>& s, const RenderSettings& settings,
                               const RenderOptions& options, const TileCallback& onTile,
                               const StopPredicate& shouldStop) {
    return Whitted1980Renderer<T>(s, settings, options, onTile, shouldStop).run();
}

template RenderResult renderWhitted1980<float>(const PreparedScene<float>&, const RenderSettings&,
                                               const RenderOptions&, const TileCallback&,
                                               const StopPredicate&);
template RenderResult renderWhitted1980<double>(const PreparedScene<double>&, const RenderSettings&,
                                                const RenderOptions&, const TileCallback&,
                                                const StopPredicate&);

}  // namespace whitted
