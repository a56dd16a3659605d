// Each sphere's shadow cone, widened as shadow_cones.cpp widens it and by a
// margin more, is bounded on every face of the cube it reaches by a rectangle
// of (u, v); the sphere goes into each cell the rectangle overlaps. Computed
// in double; the kernel looks a direction up from T, whose rounding (a few
// 1e-7 of u and v) lies far inside the margins, so a ray whose direction is in
// a sphere's cone finds that sphere in its cell.
#include "tracer/light_buffer.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <optional>

#include "base/parallel_for.h"
#include "tracer/screen_boxes.h"

namespace whitted {
namespace {

// A cone wider than asin(this) (a sphere close to the light) would fill many
// cells of every face it reaches: no buffer for that light.
constexpr double kSinWidestCone = 0.5;
// The sine and cosine of the margin added to each cone's half-angle, radians.
constexpr double kSinMargin = 1e-4, kCosMargin = 0.999999995;
constexpr double kFaceMargin = 1e-4;  // added to each rectangle in u and v
// The sine and cosine of the largest angle between a face's axis and a
// direction on that face, towards a corner of the cube: sqrt(2/3), sqrt(1/3).
constexpr double kSinFaceReach = 0.816496580927726, kCosFaceReach = 0.5773502691896258;
// Cells a face gets for each sphere seen through it (a cell then lists three
// or four on the inside field; one or two per sphere ran no faster). The most
// spheres a cell lists before its rays go through the tree instead: four
// vectors' worth with AVX-512 (clustered ran 0.96 of the time with 64 as with
// 32, the others the same). And the most cells the rectangles may cover, 16 a
// sphere on average, before the buffer is not made (huge spheres near the light).
constexpr double kCellsPerSphere = 0.5;
constexpr std::uint32_t kMostSpheresInCell = 64;
constexpr double kMostCellsPerSphere = 16.0;
constexpr int kMostCellsAcross = 4096;

struct Interval {
    double lo, hi;
};

// A sphere's rectangle on one face, in float: the margins dwarf its rounding.
struct Footprint {
    std::int32_t sphere;
    std::int32_t face;
    float uLo, uHi, vLo, vHi;
};

// The range of d[other] / d[axis] over the directions d of a cone about the
// unit vector a, whose half-angle has sine `sine`, on a face where a[axis]
// (am, signed for the face) > 0. Such a direction's projection on the
// (other, axis) plane makes an angle with the axis within alpha =
// asin(sine / rho) of a's own, phi, rho being the length of a's projection:
// the range is tan(phi -+ alpha), by the sum formula.
Interval coneRange(double am, double ao, double sine) {
    const double beyond = am * am + ao * ao - sine * sine;
    if (!(beyond > 0)) return {-HUGE_VAL, HUGE_VAL};
    const double tanPhi = ao / am, tanAlpha = sine / std::sqrt(beyond);
    const double belowLow = 1 + tanPhi * tanAlpha, belowHigh = 1 - tanPhi * tanAlpha;
    return {belowLow > 0 ? (tanPhi - tanAlpha) / belowLow - kFaceMargin : -HUGE_VAL,
            belowHigh > 0 ? (tanPhi + tanAlpha) / belowHigh + kFaceMargin : HUGE_VAL};
}

bool clipToFace(Interval& r) {
    r.lo = std::max(r.lo, -1 - kFaceMargin);
    r.hi = std::min(r.hi, 1 + kFaceMargin);
    return r.lo <= r.hi;
}

// Appends sphere k's rectangle on each face its cone reaches. False when the
// cone is too wide for a buffer.
bool addFootprints(int k, const glm::dvec3& light, const glm::dvec3& centre, double radius,
                   std::vector<Footprint>& out) {
    const glm::dvec3 fromLight = centre - light;
    const double distance = glm::length(fromLight);
    const double reach = radius + kSkipWidening * (distance + radius);
    if (!(distance > reach)) return false;
    // The sine and cosine of asin(reach / distance) + the margin.
    const double coneSine = reach / distance, coneCosine = std::sqrt(1 - coneSine * coneSine);
    const double sine = coneSine * kCosMargin + coneCosine * kSinMargin;
    if (sine > kSinWidestCone) return false;
    const double cosine = coneCosine * kCosMargin - coneSine * kSinMargin;
    // The cone reaches a face when its axis lies within kFaceReach + its
    // half-angle of the face's axis (under 90 degrees: the cone is narrow).
    const double faceCosine = kCosFaceReach * cosine - kSinFaceReach * sine;
    const glm::dvec3 a = fromLight / distance;
    for (int face = 0; face < 6; ++face) {
        const int axis = face / 2;
        const double am = face % 2 ? -a[axis] : a[axis];
        if (am <= faceCosine) continue;
        Interval u = coneRange(am, a[(axis + 1) % 3], sine);
        Interval v = coneRange(am, a[(axis + 2) % 3], sine);
        if (clipToFace(u) && clipToFace(v))
            out.push_back({k, face, float(u.lo), float(u.hi), float(v.lo), float(v.hi)});
    }
    return true;
}

struct FaceExtent {
    Interval u{HUGE_VAL, -HUGE_VAL}, v{HUGE_VAL, -HUGE_VAL};
    int footprints = 0;

    void add(const Footprint& p) {
        u = {std::min(u.lo, double(p.uLo)), std::max(u.hi, double(p.uHi))};
        v = {std::min(v.lo, double(p.vLo)), std::max(v.hi, double(p.vHi))};
        ++footprints;
    }
    void add(const FaceExtent& e) {
        u = {std::min(u.lo, e.u.lo), std::max(u.hi, e.u.hi)};
        v = {std::min(v.lo, e.v.lo), std::max(v.hi, e.v.hi)};
        footprints += e.footprints;
    }
};

// Each face's grid over the rectangle its footprints cover, about
// kCellsPerSphere cells for each. Returns the number of cells.
int layOutFaces(const FaceExtent (&extent)[6], LightBufferFace (&faces)[6]) {
    int cells = 0;
    for (int f = 0; f < 6; ++f) {
        LightBufferFace& face = faces[f];
        face = {};
        face.firstCell = cells;
        const FaceExtent& e = extent[f];
        if (!e.footprints) continue;
        const double width = e.u.hi - e.u.lo, height = e.v.hi - e.v.lo;
        const double target = std::max(1.0, kCellsPerSphere * e.footprints);
        face.nu =
            std::clamp(int(std::lround(std::sqrt(target * width / height))), 1, kMostCellsAcross);
        face.nv = std::clamp(int(std::lround(target / face.nu)), 1, kMostCellsAcross);
        face.u0 = e.u.lo;
        face.v0 = e.v.lo;
        face.cellsPerU = face.nu / width;
        face.cellsPerV = face.nv / height;
        cells += face.nu * face.nv;
    }
    return cells;
}

// The cells of its face a footprint overlaps: columns i0..i1 of rows j0..j1.
struct CellSpan {
    int i0, i1, j0, j1;
    long long count() const { return (long long)(i1 - i0 + 1) * (j1 - j0 + 1); }
};

CellSpan cellSpan(const Footprint& p, const LightBufferFace& face) {
    const auto cell = [](double x, double origin, double perCell, int n) {
        return std::clamp(int(std::floor((x - origin) * perCell)), 0, n - 1);
    };
    return {cell(p.uLo, face.u0, face.cellsPerU, face.nu),
            cell(p.uHi, face.u0, face.cellsPerU, face.nu),
            cell(p.vLo, face.v0, face.cellsPerV, face.nv),
            cell(p.vHi, face.v0, face.cellsPerV, face.nv)};
}

// A footprint's cells: `rows` rows of `columns` cells from cell0, each row
// `stride` cells after the one before.
struct Placed {
    std::int32_t sphere;
    std::int32_t cell0;
    std::int32_t stride;
    std::uint16_t columns, rows;

    long long cells() const { return (long long)columns * rows; }
};

Placed placed(const Footprint& p, const LightBufferFace& face) {
    const CellSpan s = cellSpan(p, face);
    return {p.sphere, face.firstCell + s.j0 * face.nu + s.i0, face.nu,
            std::uint16_t(s.i1 - s.i0 + 1), std::uint16_t(s.j1 - s.j0 + 1)};
}

template <typename Visit>
void forCellsOf(const Placed& p, const Visit& visit) {
    for (int row = 0, first = p.cell0; row < p.rows; ++row, first += p.stride)
        for (int cell = first; cell < first + p.columns; ++cell) visit(cell);
}

// The footprints in order of their first cell, 64 cells at a time (a stable
// counting sort), so that the passes that count and fill the cells go from
// one cache line to the next instead of all over the cells.
std::vector<Placed> inCellOrder(const std::vector<std::vector<Placed>>& chunks, int cells) {
    constexpr int kShift = 6;
    std::vector<std::uint32_t> start(std::size_t((cells >> kShift) + 2), 0);
    for (const std::vector<Placed>& chunk : chunks)
        for (const Placed& p : chunk) ++start[std::size_t((p.cell0 >> kShift) + 1)];
    for (std::size_t b = 1; b < start.size(); ++b) start[b] += start[b - 1];
    std::vector<Placed> sorted(start.back());
    for (const std::vector<Placed>& chunk : chunks)
        for (const Placed& p : chunk) sorted[start[std::size_t(p.cell0 >> kShift)]++] = p;
    return sorted;
}

// Each cell's list from the footprints in cell order; a cell with more than
// kMostSpheresInCell spheres is marked to go through the tree.
void fillCells(const std::vector<Placed>& sorted, int cells, LightBuffer& buffer) {
    std::vector<std::uint32_t> filled(std::size_t(cells), 0);
    for (const Placed& p : sorted) forCellsOf(p, [&](int cell) { ++filled[std::size_t(cell)]; });
    buffer.cells.resize(std::size_t(cells));
    std::uint32_t listed = 0;
    for (int c = 0; c < cells; ++c) {
        std::uint32_t& n = filled[std::size_t(c)];
        if (n > kMostSpheresInCell) {
            buffer.cells[std::size_t(c)] = {0, LightBufferCell::kThroughTree};
        } else {
            buffer.cells[std::size_t(c)] = {listed, n};
            listed += n;
        }
        n = 0;
    }
    buffer.spheres.resize(listed);
    for (const Placed& p : sorted)
        forCellsOf(p, [&](int cell) {
            const LightBufferCell& to = buffer.cells[std::size_t(cell)];
            if (to.count != LightBufferCell::kThroughTree)
                buffer.spheres[to.first + filled[std::size_t(cell)]++] = p.sphere;
        });
}

// The footprints of the tree's spheres, a chunk of spheres at a time, and the
// extent they cover on each face; nothing when a cone is too wide.
template <typename T>
std::optional<std::vector<std::vector<Footprint>>> footprintsOf(
    const Vec<T>& light, const SphereSet<T>& spheres, std::span<const std::int32_t> direct,
    int threads, FaceExtent (&extent)[6]) {
    const int count = spheres.count();
    std::vector<char> inTree(std::size_t(count), 1);
    for (const std::int32_t k : direct) inTree[std::size_t(k)] = 0;
    std::vector<std::vector<Footprint>> prints(std::size_t(chunkCount(count)));
    std::vector<std::array<FaceExtent, 6>> extents(prints.size());
    std::atomic<bool> tooWide{false};
    forEachChunk(count, threads, [&](int c, int begin, int end) {
        std::vector<Footprint>& out = prints[std::size_t(c)];
        out.reserve(std::size_t(2 * (end - begin)));
        for (int k = begin; k < end && !tooWide.load(std::memory_order_relaxed); ++k)
            if (inTree[std::size_t(k)] &&
                !addFootprints(k, glm::dvec3(light), spheres.centreOf(k), spheres.radiusOf(k), out))
                tooWide = true;
        for (const Footprint& p : out) extents[std::size_t(c)][p.face].add(p);
    });
    if (tooWide) return std::nullopt;
    for (const std::array<FaceExtent, 6>& chunk : extents)
        for (int f = 0; f < 6; ++f) extent[f].add(chunk[f]);
    return prints;
}

// Each footprint's cells, in cell order (inCellOrder()); nothing when they
// would cover more than kMostCellsPerSphere cells a sphere.
std::optional<std::vector<Placed>> placedInCellOrder(
    const std::vector<std::vector<Footprint>>& prints, const LightBufferFace (&faces)[6], int cells,
    int spheres, int threads) {
    std::vector<std::vector<Placed>> chunks(prints.size());
    std::vector<long long> covered(prints.size(), 0);
    // A task for each chunk of footprints.
    forEachChunk(
        int(prints.size()), threads,
        [&](int c, int, int) {
            for (const Footprint& p : prints[std::size_t(c)]) {
                chunks[std::size_t(c)].push_back(placed(p, faces[p.face]));
                covered[std::size_t(c)] += chunks[std::size_t(c)].back().cells();
            }
        },
        1);
    long long allCovered = 0;
    for (const long long n : covered) allCovered += n;
    if (double(allCovered) > kMostCellsPerSphere * spheres) return std::nullopt;
    return inCellOrder(chunks, cells);
}

}  // namespace

template <typename T>
std::shared_ptr<const LightBuffer> lightBuffer(const Vec<T>& light, const SphereSet<T>& spheres,
                                               std::span<const std::int32_t> direct, int threads) {
    threads = resolveThreadCount(threads);
    FaceExtent extent[6];
    std::optional<std::vector<std::vector<Footprint>>> prints =
        footprintsOf(light, spheres, direct, threads, extent);
    if (!prints) return nullptr;
    auto buffer = std::make_shared<LightBuffer>();
    const int cells = layOutFaces(extent, buffer->faces);
    std::optional<std::vector<Placed>> sorted =
        placedInCellOrder(*prints, buffer->faces, cells, spheres.count(), threads);
    if (!sorted) return nullptr;
    fillCells(*sorted, cells, *buffer);
    return buffer;
}

template std::shared_ptr<const LightBuffer> lightBuffer(const Vec<float>&, const SphereSet<float>&,
                                                        std::span<const std::int32_t>, int);
template std::shared_ptr<const LightBuffer> lightBuffer(const Vec<double>&,
                                                        const SphereSet<double>&,
                                                        std::span<const std::int32_t>, int);

}  // namespace whitted
