// What the sphere BVH's build and refit share (bvh.cpp, bvh_refit.cpp):
// which spheres a tree in T can bound, and boxes rounded outward to T so that
// a box never excludes a hit the sphere test would find. Internal to them.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "base/parallel_for.h"
#include "tracer/bvh.h"
#include "tracer/bvh_split.h"

namespace whitted::bvh_build {

// The largest |coordinate| + radius a sphere in the tree may have: the margin
// argument in bvh_traverse.h needs squares of such numbers to stay finite in T,
// and the nodes' boxes, in float (BvhNode), must hold them. Beyond it a sphere
// is tested directly.
template <typename T>
constexpr double kTreeReach = sizeof(T) == sizeof(float) ? 1e17 : 1e37;

template <typename T>
bool inReach(const glm::dvec3& c, double r) {
    return std::max({std::fabs(c.x), std::fabs(c.y), std::fabs(c.z)}) + r < kTreeReach<T>;
}

// Lanes rounded to float one way, with no branch: which way the nearest float
// lies is a coin toss per coordinate, and the branches of std::nextafter took
// a sixth of the build. A float's bits, read as sign and magnitude, map to an
// integer key that counts floats in order (both zeros to 0), so the next float
// down or up is the key minus or plus one.
using bvh_build::LaneInts;
inline LaneInts floatKeys(Lanes<float> x) {
    const LaneInts bits = reinterpret_cast<LaneInts>(x);
    const LaneInts magnitude = bits & 0x7fffffff;
    return bits < 0 ? -magnitude : magnitude;
}
inline Lanes<float> floatsOfKeys(LaneInts key) {
    const LaneInts bits = key < 0 ? (-key | std::int32_t(0x80000000)) : key;
    return reinterpret_cast<Lanes<float>>(bits);
}
// The lanes of x rounded to float towards -infinity.
inline Lanes<float> floatsBelow(Lanes<double> x) {
    const Lanes<float> nearest = __builtin_convertvector(x, Lanes<float>);
    const LaneInts above = __builtin_convertvector(
        __builtin_convertvector(nearest, Lanes<double>) > x, LaneInts);  // -1: one float too high
    return floatsOfKeys(floatKeys(nearest) + above);
}
// The lanes of x rounded to float towards +infinity.
inline Lanes<float> floatsAbove(Lanes<double> x) {
    const Lanes<float> nearest = __builtin_convertvector(x, Lanes<float>);
    const LaneInts below = __builtin_convertvector(
        __builtin_convertvector(nearest, Lanes<double>) < x, LaneInts);  // -1: one float too low
    return floatsOfKeys(floatKeys(nearest) - below);
}

// Lanes rounded outward to T: to float as above, unchanged in double.
template <typename T>
Lanes<T> lanesBelow(Lanes<double> x) {
    if constexpr (sizeof(T) == sizeof(float))
        return floatsBelow(x);
    else
        return x;
}
template <typename T>
Lanes<T> lanesAbove(Lanes<double> x) {
    if constexpr (sizeof(T) == sizeof(float))
        return floatsAbove(x);
    else
        return x;
}

template <typename T>
LaneBox<T> boxOf(const BvhNode& node) {
    LaneBox<T> box;
    box.grow(Lanes<T>{node.lo[0], node.lo[1], node.lo[2], 0},
             Lanes<T>{node.hi[0], node.hi[1], node.hi[2], 0});
    return box;
}

template <typename T>
void storeBox(BvhNode& node, const LaneBox<T>& box) {
    const Lanes<float> lo = floatsBelow(__builtin_convertvector(box.lo, Lanes<double>));
    const Lanes<float> hi = floatsAbove(__builtin_convertvector(box.hi, Lanes<double>));
    for (int a = 0; a < 3; ++a) {
        node.lo[a] = lo[a];
        node.hi[a] = hi[a];
    }
}

template <typename T>
Ref<T> sphereRef(const glm::dvec3& c, double r, std::int32_t sphere) {
    const Lanes<double> centre{c.x, c.y, c.z, 0};
    return {lanesBelow<T>(centre - r), lanesAbove<T>(centre + r), sphere};
}

inline LaneBox<double> sphereBox(const glm::dvec3& c, double r) {
    LaneBox<double> b;
    b.grow(Lanes<double>{c.x - r, c.y - r, c.z - r, 0},
           Lanes<double>{c.x + r, c.y + r, c.z + r, 0});
    return b;
}

// Which spheres stay out of the tree (bvh.h, SphereBvh::direct): first any a
// tree in T cannot bound, then, largest first, each one far larger than all
// the spheres smaller than it together. Only the few largest are candidates:
// each chunk of spheres keeps its own largest, on all cores (a serial pass
// took 15 ms at a million spheres), and only those are sorted (largest first,
// ties in index order).
template <typename T>
std::vector<char> keptOut(std::span<const glm::dvec3> centres, std::span<const double> radii,
                          const BvhBuildOptions& options, int threads) {
    const int n = static_cast<int>(radii.size());
    const auto larger = [&](int a, int b) {
        return radii[a] > radii[b] || (radii[a] == radii[b] && a < b);
    };
    const std::size_t wanted = std::max(options.maxDirect, 0) + 1;
    std::vector<char> out(n, 0);  // 1: out of the tree; 2, for a while: a candidate
    std::vector<std::vector<int>> chunkLargest(chunkCount(n));
    std::vector<int> chunkInReach(chunkCount(n), 0);
    // Each chunk counts and bounds in locals, stored once: neighbouring
    // chunks' entries share a cache line, and two threads writing them for
    // every sphere made these passes no faster on two cores than on one.
    forEachChunk(n, threads, [&](int c, int begin, int end) {
        std::vector<int> largest;  // largest first
        int inReachCount = 0;
        for (int i = begin; i < end; ++i) {
            if (!inReach<T>(centres[i], radii[i])) {
                out[i] = 1;
                continue;
            }
            ++inReachCount;
            if (largest.size() == wanted && !larger(i, largest.back())) continue;
            largest.insert(std::upper_bound(largest.begin(), largest.end(), i, larger), i);
            if (largest.size() > wanted) largest.pop_back();
        }
        chunkLargest[c] = std::move(largest);
        chunkInReach[c] = inReachCount;
    });
    std::vector<int> order;  // the candidates, largest first
    for (const std::vector<int>& largest : chunkLargest)
        order.insert(order.end(), largest.begin(), largest.end());
    std::sort(order.begin(), order.end(), larger);
    order.resize(std::min(order.size(), wanted));
    const int m = std::accumulate(chunkInReach.begin(), chunkInReach.end(), 0);
    const int candidates = static_cast<int>(order.size());
    // smaller[i]: the box of the spheres in reach from order[i] on, the
    // non-candidates' box summed by chunk.
    std::vector<LaneBox<double>> smaller(candidates + 1), chunkBox(chunkCount(n));
    for (int k : order) out[k] = 2;
    forEachChunk(n, threads, [&](int c, int begin, int end) {
        LaneBox<double> box;
        for (int i = begin; i < end; ++i)
            if (!out[i]) box.grow(sphereBox(centres[i], radii[i]));
        chunkBox[c] = box;
    });
    for (int k : order) out[k] = 0;
    for (const LaneBox<double>& box : chunkBox) smaller[candidates].grow(box);
    for (int i = candidates - 1; i >= 0; --i) {
        smaller[i] = smaller[i + 1];
        smaller[i].grow(sphereBox(centres[order[i]], radii[order[i]]));
    }
    for (int i = 0; i < std::min(options.maxDirect, m - 1); ++i) {
        const LaneBox<double>& rest = smaller[i + 1];
        if (!(2.0 * radii[order[i]] > options.hugeRatio * rest.extent(rest.longestAxis()))) break;
        out[order[i]] = 1;
    }
    return out;
}

}  // namespace whitted::bvh_build
