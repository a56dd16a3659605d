// Node width of the sphere BVH, to choose it for the SIMD width by measuring
// 2-, 4- and 8-wide: the renderer's binary tree against 4- and 8-wide trees
// collapsed from it, on the same rays, with the same sphere test. A measurement
// only: the renderer's tree is not changed.
//
//   build/bin/bench_node_width [--sizes N,N,...] [--width W] [--height H]
//                              [--row-step S] [--random M] [--reps R] [--no-counts]
//                              [--layout NAME] [--blocks W] [--regroup B] [--known-hits]
//
// Defaults: N = 1000,100000,1000000 balls of app/field/sphere_field.h (the
// scene of `whitted-field N` and bench_scaling), 1280x720, every row, 200,000
// random rays, 5 repetitions, the "field" layout (app/field/field_layouts.h).
// One thread.
//
// Ray sets, each traced in packets (the kernel's lane width, 8 floats with
// AVX2) and one ray at a time:
//  * camera:  the camera rays of every S-th image row, 8 neighbouring pixels
//             of a row to a packet, as kernelCameraRow() forms them;
//  * reflect: the reflected rays at the camera rays' first hits, packed as
//             tracePacket() packs them (the hit lanes of a camera packet);
//  * random:  random points in the field's box, random directions, 8 to a packet;
//  * with --blocks W: the camera rays of blocks of pixels W wide and as many
//             rows as fill a packet, every row, and their reflections (what
//             traceCameraRows() packs: 4 x 4 with AVX-512's 16 float lanes);
//  * with --regroup B: the reflected rays at the first reflections' hits
//             ("reflect2"), and the reflect, reflect2 and random sets again,
//             each run of B rays in their order sorted (regroup()) before
//             they are packed: what regrouping bounces into coherent packets
//             would buy the traversal, the sort itself not timed.
//
// With --known-hits, each set also gets a row counted with every ray's nearest
// hit known before the walk starts ("2 (ours), hit known"; not timed): the
// nodes and spheres any walk of this tree must visit, since a box nearer than
// the hit may hold a nearer one. Its gap to the "2 (ours)" row is all that a
// better order of visiting the children could save.
//
// Trees:
//  * "2 (ours)": the renderer's own bvhClosestHits() (bvh_traverse.h) on its
//       tree; one ray is a packet with one lane, as kernelClosestHit() traces it;
//  * 4, 8: the binary tree collapsed (below). A packet tests the children one
//       after another, SIMD over the lanes, with boxLanes()'s arithmetic; one ray
//       tests all children at once, SIMD over the children (Embree's BVH4/BVH8
//       single-ray scheme);
//  * 2: the binary tree unchanged, in the wide layout, through the wide
//       traversal: a control that tells the width's effect from the traversal's.
// Every tree tests spheres with closestUpdate() (the renderer's test and its
// tie rule), so each ray must find the same (t, sphere) in every tree: the
// mismatch count printed is against "2 (ours)" in packets. The process exits
// with 1 if any ray differs.
//
// Each measured pass follows an unmeasured one through the same tree. Under
// `valgrind --tool=callgrind --instr-atstart=no --collect-atstart=no`, each
// measured pass is collected alone and dumped with its name (set/mode/tree);
// benchmarks/node_width_callgrind.py turns the dumps into figures per ray.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "base/elapsed.h"
#include "field_layouts.h"
#include "tracer/bvh.h"
#include "tracer/bvh_traverse.h"
#include "tracer/ray_packet.h"
#include "tracer/tracer.h"

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#else
#define CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_TOGGLE_COLLECT
#define CALLGRIND_ZERO_STATS
#define CALLGRIND_DUMP_STATS_AT(name)
#endif

namespace {

using namespace whitted;

using V = Simd<float>::type;
using Packet = RayPacket<float>;
// The tree and traversal the renderer has: bvhClosestHits() on the binary tree.
constexpr int kOurs = 0;
constexpr int kLanes = Packet::kWidth;

// ---------------------------------------------------------------------------
// Wide trees

// A node of W children, each child's box in SoA arrays (Embree's BVH4 and
// BVH8 layout: 128 and 256 bytes), so that one ray tests all W boxes at once.
template <int W>
struct alignas(64) WideNode {
    float lo[3][W], hi[3][W];  // the children's boxes, the binary tree's values unchanged
    std::int32_t first[W];     // inner child: its node's index; leaf: its first leaf sphere
    std::int32_t count[W];     // inner child: -1; leaf: its spheres (>= 1); empty slot: 0
};

template <int W>
struct WideBvh {
    std::vector<WideNode<W>> nodes;  // nodes[0] is the root
    int depth = 0;
};

float halfArea(const BvhNode& n) {
    const float x = n.hi[0] - n.lo[0], y = n.hi[1] - n.lo[1], z = n.hi[2] - n.lo[2];
    return x * y + y * z + z * x;
}

// The binary nodes that become the children of a wide node made from binary
// node `b`: its two children, then, while fewer than W, the inner one of
// largest surface area replaced by its own two (the usual greedy collapse:
// the node most rays enter is opened first).
template <int W>
int wideChildren(const BvhArray<BvhNode>& bin, int b, int (&kids)[W]) {
    if (bin[b].count > 0) {  // a leaf root: one child, itself
        kids[0] = b;
        return 1;
    }
    int n = 0;
    kids[n++] = bin[b].first;
    kids[n++] = bin[b].first + 1;
    while (n < W) {
        int open = -1;
        for (int i = 0; i < n; ++i)
            if (bin[kids[i]].count < 0 &&
                (open < 0 || halfArea(bin[kids[i]]) > halfArea(bin[kids[open]])))
                open = i;
        if (open < 0) break;
        const int first = bin[kids[open]].first;
        kids[open] = first;
        kids[n++] = first + 1;
    }
    return n;
}

template <int W>
int collapse(const BvhArray<BvhNode>& bin, int b, WideBvh<W>& out, int depth) {
    out.depth = std::max(out.depth, depth);
    int kids[W];
    const int n = wideChildren<W>(bin, b, kids);
    const int me = static_cast<int>(out.nodes.size());
    out.nodes.emplace_back();
    for (int c = 0; c < W; ++c) {
        WideNode<W>& node = out.nodes[me];  // again each time: the recursion grows the vector
        for (int a = 0; a < 3; ++a) {
            node.lo[a][c] = c < n ? bin[kids[c]].lo[a] : 0.0f;
            node.hi[a][c] = c < n ? bin[kids[c]].hi[a] : 0.0f;
        }
        node.count[c] = c < n ? std::max(bin[kids[c]].count, -1) : 0;
        node.first[c] = c < n ? bin[kids[c]].first : 0;
        if (c < n && bin[kids[c]].count < 0) {
            const int child = collapse(bin, kids[c], out, depth + 1);
            out.nodes[me].first[c] = child;
        }
    }
    return me;
}

template <int W>
WideBvh<W> collapseBvh(const SphereBvh<float>& bvh) {
    WideBvh<W> wide;
    wide.nodes.reserve(bvh.nodes.size() / (W - 1) + 1);
    if (!bvh.nodes.empty()) collapse<W>(bvh.nodes, 0, wide, 0);
    return wide;
}

// ---------------------------------------------------------------------------
// What the traversals count, in the counting pass only (not the timed ones).

struct Counts {
    std::uint64_t nodes = 0;    // inner nodes entered: their children's boxes are tested
    std::uint64_t boxes = 0;    // box tests (a packet's: one, for all its lanes)
    std::uint64_t spheres = 0;  // leaf sphere tests (a packet's: one); the floor not included
    bool hitKnown = false;      // set by the caller: "2 (ours)" counts a walk told its hits first
};

template <bool kCount>
void testLeaf(const SphereSet<float>& spheres, const SphereBvh<float>& bvh, int first, int count,
              const Packet& r, unsigned lanes, V& tBest, V& kBest, Counts* c) {
    for (int i = first; i < first + count; ++i)
        closestUpdate(spheres, bvh.leafSpheres[i], r, lanes, tBest, kBest);
    if constexpr (kCount) c->spheres += count;
}

// ---------------------------------------------------------------------------
// Binary: the renderer's traverseBvh() with counters, for the counting pass;
// the timed passes call bvhClosestHits() itself. It tests the root's box, then
// both children's boxes at each inner node it enters.

void binaryCounted(const SphereSet<float>& spheres, const SphereBvh<float>& bvh, const Packet& r,
                   V& tBest, V& kBest, Counts* c) {
    const PacketSlabs<float> slabs = packetSlabs(r, treeReach(bvh));
    if (!bvhClosestStart(spheres, bvh, r, slabs, tBest, kBest)) return;
    if (c->hitKnown) {  // an uncounted walk first: tBest is then each lane's hit
        const auto leaf = [&](const BvhNode& node, unsigned in) {
            testLeaf<false>(spheres, bvh, node.first, node.count, r, in, tBest, kBest, c);
            return ~0u;
        };
        traverseBvh(spheres, bvh, slabs, tBest, r.active, leaf);
    }
    ++c->boxes;
    const auto leaf = [&](const BvhNode& node, unsigned in) {
        testLeaf<true>(spheres, bvh, node.first, node.count, r, in, tBest, kBest, c);
        return ~0u;
    };
    const auto inner = [&] {
        ++c->nodes;
        c->boxes += 2;
    };
    traverseBvh(spheres, bvh, slabs, tBest, r.active, leaf, inner);
}

// ---------------------------------------------------------------------------
// Wide, packets: children one after another, SIMD over the lanes.

// slabLanes() for child c of a wide node: the renderer's box test, so the
// same lanes pass, with each lane's entry distance.
template <int W>
unsigned childLanes(const WideNode<W>& node, int c, const PacketSlabs<float>& s, const V& limit,
                    unsigned lanes, V& entry) {
    const float lo[3] = {node.lo[0][c], node.lo[1][c], node.lo[2][c]};
    const float hi[3] = {node.hi[0][c], node.hi[1][c], node.hi[2][c]};
    return slabLanes(lo, hi, s, limit, lanes, entry);
}

// A stacked child: its lanes and their entry distances when its parent was
// entered, so that a pop skips lanes whose nearest hit has since come closer
// (Embree's packet traversal keeps the same).
struct PacketEntry {
    V entry;
    unsigned lanes;
    std::int32_t first, count;
};

struct Hit {
    float key;
    int slot;
};

// Insertion sort, nearest first: at most 8 children.
void sortHits(Hit* hits, int n) {
    for (int i = 1; i < n; ++i) {
        const Hit h = hits[i];
        int j = i;
        for (; j > 0 && hits[j - 1].key > h.key; --j) hits[j] = hits[j - 1];
        hits[j] = h;
    }
}

// Pushes the children of `node` that some lane meets, the farthest first, so
// the nearest is popped next. Near and far by the entry distance of the
// node's lowest lane (the binary traversal orders by that lane too).
template <int W, bool kCount>
void pushPacketChildren(const WideNode<W>& node, const PacketSlabs<float>& slabs, const V& limit,
                        unsigned lanes, PacketEntry* stack, int& top, Counts* c) {
    const int lead = __builtin_ctz(lanes);
    Hit hits[W];
    V entries[W];
    unsigned in[W];
    int n = 0;
    for (int k = 0; k < W && node.count[k] != 0; ++k) {
        if constexpr (kCount) ++c->boxes;
        in[k] = childLanes(node, k, slabs, limit, lanes, entries[k]);
        if (!in[k]) continue;
        const bool leads = (in[k] >> lead) & 1u;
        hits[n++] = {leads ? entries[k][lead] : std::numeric_limits<float>::infinity(), k};
    }
    sortHits(hits, n);
    for (int i = n - 1; i >= 0; --i) {
        const int k = hits[i].slot;
        stack[top++] = {entries[k], in[k], node.first[k], node.count[k]};
    }
}

template <int W, bool kCount>
void widePacket(const SphereSet<float>& spheres, const SphereBvh<float>& bvh,
                const WideBvh<W>& wide, const Packet& r, V& tBest, V& kBest, Counts* c) {
    const PacketSlabs<float> slabs = packetSlabs(r, treeReach(bvh));
    if (!bvhClosestStart(spheres, bvh, r, slabs, tBest, kBest)) return;
    PacketEntry stack[(W - 1) * kMaxBvhDepth + 2];
    int top = 0;
    stack[top++] = {V{} - std::numeric_limits<float>::infinity(), r.active, 0, -1};
    while (top > 0) {
        const PacketEntry& e = stack[--top];
        const unsigned lanes = e.lanes & ~laneBits(e.entry > tBest);  // NaN keeps its lane
        if (!lanes) continue;
        if (e.count > 0) {
            testLeaf<kCount>(spheres, bvh, e.first, e.count, r, lanes, tBest, kBest, c);
            continue;
        }
        if constexpr (kCount) ++c->nodes;
        pushPacketChildren<W, kCount>(wide.nodes[e.first], slabs, tBest, lanes, stack, top, c);
    }
}

// ---------------------------------------------------------------------------
// Wide, one ray: all W children's boxes at once, SIMD over the children.

template <int W>
struct ChildVec;
template <>
struct ChildVec<2> {
    typedef float type __attribute__((vector_size(8)));
    typedef std::int32_t ints __attribute__((vector_size(8)));
};
template <>
struct ChildVec<4> {
    typedef float type __attribute__((vector_size(16)));
    typedef std::int32_t ints __attribute__((vector_size(16)));
};
template <>
struct ChildVec<8> {
    typedef float type __attribute__((vector_size(32)));
    typedef std::int32_t ints __attribute__((vector_size(32)));
};

// One instruction where the build has it; a portable build (no AVX) takes
// the loop for eight children.
template <typename M>
unsigned childBits(const M& m) {
#ifdef __AVX__
    if constexpr (sizeof(M) == 32)
        return static_cast<unsigned>(_mm256_movemask_ps(reinterpret_cast<__m256>(m)));
#endif
    if constexpr (sizeof(M) == 16)
        return static_cast<unsigned>(_mm_movemask_ps(reinterpret_cast<__m128>(m)));
    unsigned bits = 0;
    for (unsigned c = 0; c < sizeof(M) / sizeof(m[0]); ++c) bits |= (m[c] ? 1u : 0u) << c;
    return bits;
}

// By reference: returning a 32-byte vector by value changes the ABI in a
// build without AVX (GCC's -Wpsabi).
template <typename Vec>
void loadInto(Vec& v, const void* p) {
    std::memcpy(&v, p, sizeof v);
}

// One ray's slab values (lane 0 of its PacketSlabs: the same numbers).
struct RaySlabs {
    float originPlus[3], originMinus[3], inv[3];
};

// The children of `node` the ray meets within [0, limit], as bits, and their
// entry distances: boxLanes()'s operations per child, in the same order.
template <int W>
unsigned childHits(const WideNode<W>& node, const RaySlabs& s, float limit,
                   typename ChildVec<W>::type& entry) {
    using CV = typename ChildVec<W>::type;
    CV near, far;
    CV lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
        loadInto(lo[a], node.lo[a]);
        loadInto(hi[a], node.hi[a]);
    }
    for (int a = 0; a < 3; ++a) {
        const CV p = (lo[a] - s.originPlus[a]) * s.inv[a];
        const CV q = (hi[a] - s.originMinus[a]) * s.inv[a];
        const CV n = p < q ? p : q, f = p < q ? q : p;
        near = a == 0 ? n : (near > n ? near : n);
        far = a == 0 ? f : (far < f ? far : f);
    }
    entry = near;
    const auto miss = (near > far) | (far < 0.0f) | (near > limit);
    typename ChildVec<W>::ints counts;
    loadInto(counts, node.count);
    const unsigned filled = childBits(counts != 0);
    return filled & ~childBits(miss);
}

struct RayEntry {
    float entry;
    std::int32_t first, count;
};

template <int W>
void pushRayChildren(const WideNode<W>& node, const RaySlabs& s, float limit, RayEntry* stack,
                     int& top) {
    typename ChildVec<W>::type entry;
    unsigned bits = childHits<W>(node, s, limit, entry);
    Hit hits[W];
    int n = 0;
    for (; bits; bits &= bits - 1) {
        const int k = __builtin_ctz(bits);
        hits[n++] = {entry[k], k};
    }
    sortHits(hits, n);
    for (int i = n - 1; i >= 0; --i) {
        const int k = hits[i].slot;
        stack[top++] = {hits[i].key, node.first[k], node.count[k]};
    }
}

RaySlabs raySlabs(const PacketSlabs<float>& s) {
    return {{s.originPlus[0][0], s.originPlus[1][0], s.originPlus[2][0]},
            {s.originMinus[0][0], s.originMinus[1][0], s.originMinus[2][0]},
            {s.ix[0], s.iy[0], s.iz[0]}};
}

// `r` holds one ray, in lane 0; the sphere tests are the packets' own.
template <int W, bool kCount>
void wideRay(const SphereSet<float>& spheres, const SphereBvh<float>& bvh, const WideBvh<W>& wide,
             const Packet& r, V& tBest, V& kBest, Counts* c) {
    const PacketSlabs<float> slabs = packetSlabs(r, treeReach(bvh));
    if (!bvhClosestStart(spheres, bvh, r, slabs, tBest, kBest)) return;
    const RaySlabs s = raySlabs(slabs);
    RayEntry stack[(W - 1) * kMaxBvhDepth + 2];
    int top = 0;
    stack[top++] = {-std::numeric_limits<float>::infinity(), 0, -1};
    while (top > 0) {
        const RayEntry e = stack[--top];
        if (e.entry > tBest[0]) continue;  // NaN: kept
        if (e.count > 0) {
            testLeaf<kCount>(spheres, bvh, e.first, e.count, r, 1u, tBest, kBest, c);
            continue;
        }
        if constexpr (kCount) {
            ++c->nodes;
            for (int k = 0; k < W; ++k) c->boxes += wide.nodes[e.first].count[k] != 0;
        }
        pushRayChildren<W>(wide.nodes[e.first], s, tBest[0], stack, top);
    }
}

// ---------------------------------------------------------------------------
// The scene and its rays

struct Bench {
    PreparedScene<float> scene;
    WideBvh<2> wide2;  // the binary tree again, in the wide layout
    WideBvh<4> wide4;
    WideBvh<8> wide8;
    const SphereBvh<float>& bvh() const { return *scene.bvh; }
    const SphereSet<float>& spheres() const { return scene.spheres; }
    template <int W>
    const WideBvh<W>& wide() const {
        if constexpr (W == 2)
            return wide2;
        else if constexpr (W == 4)
            return wide4;
        else
            return wide8;
    }
};

struct RaySet {
    const char* name;
    std::vector<Packet> packets;
    std::size_t rays = 0;
};

std::size_t countRays(const std::vector<Packet>& packets) {
    std::size_t n = 0;
    for (const Packet& p : packets) n += __builtin_popcount(p.active);
    return n;
}

// traceCameraPacket()'s directions for the pixel centres of row y, x0 .. x0+m-1.
Packet cameraPacket(const CameraBasis<float>& cam, int y, int x0, int m) {
    V x{};
    for (int l = 0; l < kLanes; ++l) x[l] = float(x0 + l) + 0.5f;
    V yy = V{} + (float(y) + 0.5f);
    x = (x / float(cam.width) * 2.0f - 1.0f) * cam.tanHalfFov * cam.aspect;
    yy = (1.0f - yy / float(cam.height) * 2.0f) * cam.tanHalfFov;
    const Vec3x<float> dir =
        normalize(Vec3x<float>::broadcast(cam.forward) + x * Vec3x<float>::broadcast(cam.right) +
                  yy * Vec3x<float>::broadcast(cam.up));
    return Packet::of(Vec3x<float>::broadcast(cam.origin), dir, V{} - 1.0f, Packet::Mask{},
                      (1u << m) - 1, true);
}

// The camera rays of a block of pixel centres, (x0, y0) its top left, `side`
// pixels wide and as many rows as fill the lanes, lane l at
// (x0 + l % side, y0 + l / side); lanes off the image left empty.
Packet blockPacket(const CameraBasis<float>& cam, int x0, int y0, int side) {
    V x{}, yy{};
    unsigned active = 0;
    for (int l = 0; l < kLanes; ++l) {
        const int px = x0 + l % side, py = y0 + l / side;
        x[l] = float(px) + 0.5f;
        yy[l] = float(py) + 0.5f;
        if (px < cam.width && py < cam.height) active |= 1u << l;
    }
    x = (x / float(cam.width) * 2.0f - 1.0f) * cam.tanHalfFov * cam.aspect;
    yy = (1.0f - yy / float(cam.height) * 2.0f) * cam.tanHalfFov;
    const Vec3x<float> dir =
        normalize(Vec3x<float>::broadcast(cam.forward) + x * Vec3x<float>::broadcast(cam.right) +
                  yy * Vec3x<float>::broadcast(cam.up));
    return Packet::of(Vec3x<float>::broadcast(cam.origin), dir, V{} - 1.0f, Packet::Mask{}, active,
                      true);
}

RaySet blockRays(const Bench& b, int side) {
    const CameraBasis<float>& cam = b.scene.camera;
    RaySet set{"camera, blocks", {}, 0};
    for (int y = 0; y < cam.height; y += kLanes / side)
        for (int x0 = 0; x0 < cam.width; x0 += side)
            set.packets.push_back(blockPacket(cam, x0, y, side));
    set.rays = countRays(set.packets);
    return set;
}

RaySet cameraRays(const Bench& b, int rowStep) {
    const CameraBasis<float>& cam = b.scene.camera;
    RaySet set{"camera", {}, 0};
    for (int y = 0; y < cam.height; y += rowStep)
        for (int x0 = 0; x0 < cam.width; x0 += kLanes)
            set.packets.push_back(cameraPacket(cam, y, x0, std::min(kLanes, cam.width - x0)));
    set.rays = countRays(set.packets);
    return set;
}

// tracePacket()'s reflected packet for the hit lanes of `r`.
Packet reflectPacket(const Bench& b, const Packet& r) {
    V t, k;
    bvhClosestHits(b.spheres(), b.bvh(), r, t, k);
    const unsigned lanes = laneBits((k >= 0.0f) & maskFromBits<float>(r.active));
    Vec3x<float> centre;
    for (unsigned bits = lanes; bits; bits &= bits - 1) {
        const int l = __builtin_ctz(bits);
        centre.setLane(l, b.spheres().centre[static_cast<int>(k[l])]);
    }
    const Vec3x<float> d = r.dirs();
    const Vec3x<float> p = r.origins() + t * d;
    const Vec3x<float> outward = normalize(p - centre);
    const auto inside = dot(d, outward) > 0.0f;
    const Vec3x<float> n = select(inside, -outward, outward);
    return Packet::of(p, d - (2.0f * dot(d, n)) * n, k, inside, lanes);
}

RaySet reflectRays(const Bench& b, const RaySet& camera) {
    RaySet set{"reflect", {}, 0};
    for (const Packet& r : camera.packets) {
        const Packet p = reflectPacket(b, r);
        if (p.active) set.packets.push_back(p);
    }
    set.rays = countRays(set.packets);
    return set;
}

// Every third bit of v's low 10 bits spread out, for a 30-bit Morton code.
std::uint32_t spreadBits(std::uint32_t v) {
    v = (v | (v << 16)) & 0x030000FF;
    v = (v | (v << 8)) & 0x0300F00F;
    v = (v | (v << 4)) & 0x030C30C3;
    return (v | (v << 2)) & 0x09249249;
}

// The rays of `set` again, sorted by their direction's octant and then along
// a Morton curve through their origins, `batch` rays at a time, kLanes to a
// packet: bounces regrouped so that a packet's rays start near one another
// and go the same way. Prints what the regrouping itself took, step by step:
// a renderer would make its rays in place and keyed, and pack them as it
// traces, so the sort is the part that tells whether regrouping can pay.
RaySet regroup(const RaySet& set, const char* name, std::size_t batch) {
    struct Entry {
        std::uint64_t key;
        Vec<float> o, d;
        int sphere;
        bool into;
    };
    const auto start = std::chrono::steady_clock::now();
    std::vector<Entry> rays;
    Vec<float> lo(1e30f, 1e30f, 1e30f), hi(-1e30f, -1e30f, -1e30f);
    for (const Packet& p : set.packets)
        for (unsigned bits = p.active; bits; bits &= bits - 1) {
            const int l = __builtin_ctz(bits);
            const Vec<float> o = p.origin(l);
            rays.push_back({0, o, p.dir(l), int(p.originSphere[l]), p.intoOrigin[l] != 0});
            lo = Vec<float>(std::min(lo.x, o.x), std::min(lo.y, o.y), std::min(lo.z, o.z));
            hi = Vec<float>(std::max(hi.x, o.x), std::max(hi.y, o.y), std::max(hi.z, o.z));
        }
    auto cell = [](float v, float a, float b) {
        return std::uint32_t(
            std::clamp((v - a) / std::max(b - a, 1e-20f) * 1023.0f, 0.0f, 1023.0f));
    };
    const double gathered = secondsSince(start);
    for (Entry& e : rays) {
        const std::uint32_t octant =
            (e.d.x < 0 ? 4u : 0u) | (e.d.y < 0 ? 2u : 0u) | (e.d.z < 0 ? 1u : 0u);
        const std::uint32_t morton = spreadBits(cell(e.o.x, lo.x, hi.x)) << 2 |
                                     spreadBits(cell(e.o.y, lo.y, hi.y)) << 1 |
                                     spreadBits(cell(e.o.z, lo.z, hi.z));
        e.key = std::uint64_t(octant) << 32 | morton;
    }
    const double keyed = secondsSince(start);
    for (std::size_t b0 = 0; b0 < rays.size(); b0 += batch)
        std::stable_sort(rays.begin() + b0, rays.begin() + std::min(rays.size(), b0 + batch),
                         [](const Entry& a, const Entry& b) { return a.key < b.key; });
    const double sorted = secondsSince(start);
    RaySet out{name, {}, 0};
    for (std::size_t i = 0; i < rays.size(); i += kLanes) {
        Packet p;
        p.active = 0;
        for (std::size_t l = 0; l < kLanes && i + l < rays.size(); ++l) {
            const Entry& e = rays[i + l];
            p.set(int(l), e.o, e.d, e.sphere, e.into);
        }
        out.packets.push_back(p);
    }
    out.rays = countRays(out.packets);
    const double packed = secondsSince(start);
    std::printf(
        "%s: %zu rays regrouped in %.1f ms (gathered %.1f, keyed %.1f, sorted %.1f, "
        "packed %.1f)\n",
        name, out.rays, packed * 1e3, gathered * 1e3, (keyed - gathered) * 1e3,
        (sorted - keyed) * 1e3, (packed - sorted) * 1e3);
    return out;
}

// Origins in the balls' box (x in [-50, 50], y in [-0.5, 0.1], z in [1.5,
// 100], less the camera position: the prepared scene's frame), directions
// uniform on the sphere.
RaySet randomRays(int count) {
    std::mt19937 rng(12);
    std::uniform_real_distribution<float> x(-50.0f, 50.0f), y(-0.85f, -0.25f), z(2.5f, 101.0f);
    std::normal_distribution<float> g;
    RaySet set{"random", {}, 0};
    for (int i = 0; i < count; i += kLanes) {
        Packet p;
        for (int l = 0; l < kLanes && i + l < count; ++l) {
            const Vec<float> o(x(rng), y(rng), z(rng));
            Vec<float> d(g(rng), g(rng), g(rng));
            d = d * (1.0f / std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z));
            p.set(l, o, d, -1, false);
        }
        set.packets.push_back(p);
    }
    set.rays = countRays(set.packets);
    return set;
}

// ---------------------------------------------------------------------------
// Passes

enum class Mode { packet, single };

// One ray set through one width in one mode: every ray's (t, sphere) into
// out (8 slots per packet), the counters when kCount.
// Each tree's traversal is compiled whole, everything it calls inlined
// (flatten), into a function of its own (noinline), this one and
// traceRayInto(): the same code whatever the rest of the file is. Left to
// GCC's inlining budgets, a change elsewhere in the file moved the 8-wide
// packets from 9.7k to 12.3k instructions per random ray at 1M spheres, and
// bvhClosestHits() was inlined into one build's loop and called in another's.
template <int W, bool kCount>
__attribute__((noinline, flatten)) void tracePacketInto(const Bench& b, const Packet& r, V& t, V& k,
                                                        Counts* c) {
    if constexpr (W == kOurs) {
        if constexpr (kCount)
            binaryCounted(b.spheres(), b.bvh(), r, t, k, c);
        else
            bvhClosestHits(b.spheres(), b.bvh(), r, t, k);
    } else {
        widePacket<W, kCount>(b.spheres(), b.bvh(), b.wide<W>(), r, t, k, c);
    }
}

// Lane l of `r` alone, built into a one-lane packet here, where the traversal
// sees it made, as kernelClosestHit() builds its packet before
// sceneClosestHits(): the compiler may then drop what the empty lanes need.
template <int W, bool kCount>
__attribute__((noinline, flatten)) void traceRayInto(const Bench& b, const Packet& r, int l,
                                                     float& t, float& k, Counts* c) {
    Packet one;
    one.set(0, r.origin(l), r.dir(l), static_cast<int>(r.originSphere[l]), r.intoOrigin[l] != 0);
    one.fromCamera = r.fromCamera;
    V tBest, kBest;
    if constexpr (W == kOurs && kCount)
        binaryCounted(b.spheres(), b.bvh(), one, tBest, kBest, c);
    else if constexpr (W == kOurs)
        bvhClosestHits(b.spheres(), b.bvh(), one, tBest, kBest);
    else
        wideRay<W, kCount>(b.spheres(), b.bvh(), b.wide<W>(), one, tBest, kBest, c);
    t = tBest[0];
    k = kBest[0];
}

struct Result {
    std::vector<float> t, k;  // per packet slot
};

template <int W, bool kCount>
void runPass(const Bench& b, const RaySet& set, Mode mode, Result& out, Counts* c) {
    // Sized once: a timed pass writes its rays' slots and nothing else, so that
    // it is not charged for a fresh array's first touch.
    if (out.t.size() != set.packets.size() * kLanes) {
        out.t.assign(set.packets.size() * kLanes, 0.0f);
        out.k.assign(set.packets.size() * kLanes, -2.0f);
    }
    for (std::size_t i = 0; i < set.packets.size(); ++i) {
        const Packet& r = set.packets[i];
        V t, k;
        if (mode == Mode::packet) {
            tracePacketInto<W, kCount>(b, r, t, k, c);
            for (unsigned bits = r.active; bits; bits &= bits - 1) {
                const int l = __builtin_ctz(bits);
                out.t[i * kLanes + l] = t[l];
                out.k[i * kLanes + l] = k[l];
            }
            continue;
        }
        for (unsigned bits = r.active; bits; bits &= bits - 1) {
            const int l = __builtin_ctz(bits);
            traceRayInto<W, kCount>(b, r, l, out.t[i * kLanes + l], out.k[i * kLanes + l], c);
        }
    }
}

template <bool kCount>
void runWidth(int width, const Bench& b, const RaySet& set, Mode mode, Result& out, Counts* c) {
    if (width == kOurs)
        runPass<kOurs, kCount>(b, set, mode, out, c);
    else if (width == 2)
        runPass<2, kCount>(b, set, mode, out, c);
    else if (width == 4)
        runPass<4, kCount>(b, set, mode, out, c);
    else
        runPass<8, kCount>(b, set, mode, out, c);
}

// Rays whose (t, sphere) differs from the reference's, bit for bit.
std::size_t mismatches(const Result& a, const Result& ref) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < ref.k.size(); ++i)
        n += a.k[i] != ref.k[i] || std::memcmp(&a.t[i], &ref.t[i], sizeof(float)) != 0;
    return n;
}

// ---------------------------------------------------------------------------
// Driver

struct Options {
    std::vector<int> sizes = {1000, 100000, 1000000};
    int width = 1280, height = 720;
    int rowStep = 1;
    int random = 200000;
    int reps = 5;
    int blocks = 0;           // the width of the camera's blocks of pixels; 0: no such sets
    std::size_t regroup = 0;  // rays regrouped together; 0: no regrouped sets
    bool counts = true;
    bool knownHits = false;  // also count walks told each ray's hit first
    std::string layout = "field";
};

Options parseOptions(int argc, char** argv) {
    Options o;
    CLI::App app{"Node widths 2, 4 and 8 against ours (see the source's top)"};
    app.add_option("--sizes", o.sizes, "Sphere counts, e.g. 1000,100000")->delimiter(',');
    app.add_option("--width", o.width, "Image width");
    app.add_option("--height", o.height, "Image height");
    app.add_option("--row-step", o.rowStep, "Trace every this many rows")
        ->check(CLI::PositiveNumber);
    app.add_option("--random", o.random, "Random rays");
    app.add_option("--blocks", o.blocks,
                   "Also trace the camera rays of blocks of pixels this wide, as many rows as "
                   "fill a packet, every row, and their reflections");
    app.add_option(
        "--regroup", o.regroup,
        "Also trace second reflections, and each set regrouped this many rays at a time");
    app.add_option("--reps", o.reps, "Repetitions")->check(CLI::PositiveNumber);
    app.add_flag("!--no-counts", o.counts, "Skip the counting traversals");
    app.add_flag("--known-hits", o.knownHits,
                 "Also count the walks of ours told each ray's nearest hit first");
    app.add_option("--layout", o.layout, "Field layout (whitted-field --layout)")
        ->check(CLI::IsMember(fieldLayoutNames()));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        std::exit(app.exit(e) == 0 ? 0 : 2);  // help: 0; a bad flag: 2, as before
    }
    return o;
}

constexpr int kTrees = 4;
constexpr int kWidths[kTrees] = {kOurs, 2, 4, 8};
const char* const kTreeNames[kTrees] = {"2 (ours)", "2", "4", "8"};
constexpr Mode kModes[] = {Mode::packet, Mode::single};

const char* modeName(Mode m) {
    return m == Mode::packet ? "packet" : "single";
}

// One pass per (mode, width), repeated; widths interleaved within a
// repetition so that a swing in the machine's load falls on all of them.
// Returns the median seconds, [mode][width].
std::vector<std::vector<double>> timeSet(const Bench& b, const RaySet& set, const Result& ref,
                                         int reps, std::size_t& mismatch) {
    std::vector<std::vector<std::vector<double>>> s(2, std::vector<std::vector<double>>(kTrees));
    Result out = ref;  // already sized and touched
    for (int rep = 0; rep < reps; ++rep)
        for (int m = 0; m < 2; ++m)
            for (int w = 0; w < kTrees; ++w) {
                // A pass first with the same tree, not measured: caches then
                // hold this tree, as in a render, not the tree of the pass before.
                runWidth<false>(kWidths[w], b, set, kModes[m], out, nullptr);
                CALLGRIND_ZERO_STATS;
                CALLGRIND_TOGGLE_COLLECT;
                const auto start = std::chrono::steady_clock::now();
                runWidth<false>(kWidths[w], b, set, kModes[m], out, nullptr);
                s[m][w].push_back(secondsSince(start));
                CALLGRIND_TOGGLE_COLLECT;
                const std::string name =
                    std::string(set.name) + "/" + modeName(kModes[m]) + "/" + kTreeNames[w];
                CALLGRIND_DUMP_STATS_AT(name.c_str());
                if (rep == 0) mismatch += mismatches(out, ref);
            }
    std::vector<std::vector<double>> median(2, std::vector<double>(kTrees));
    for (int m = 0; m < 2; ++m)
        for (int w = 0; w < kTrees; ++w) {
            std::vector<double>& v = s[m][w];
            std::sort(v.begin(), v.end());
            median[m][w] = v[v.size() / 2];
        }
    return median;
}

// The counters per ray, as three table cells.
std::string perRay(const Counts& c, double rays) {
    char text[64];
    std::snprintf(text, sizeof text, "%.2f | %.2f | %.2f", double(c.nodes) / rays,
                  double(c.boxes) / rays, double(c.spheres) / rays);
    return text;
}

void printSet(const Bench& b, const RaySet& set, const Options& o, int n, std::size_t& mismatch) {
    Result ref;
    runPass<kOurs, false>(b, set, Mode::packet, ref, nullptr);
    const auto seconds = timeSet(b, set, ref, o.reps, mismatch);
    for (int m = 0; m < 2; ++m)
        for (int w = 0; w < kTrees; ++w) {
            Counts c;
            if (o.counts) {  // the counting traversals must find the same hits too
                Result out;
                runWidth<true>(kWidths[w], b, set, kModes[m], out, &c);
                mismatch += mismatches(out, ref);
            }
            const double rays = double(set.rays);
            // The speed against the renderer's own traversal in the same mode:
            // medians of passes taken in turn, so a ratio survives a load swing
            // that moves both.
            std::printf("| %d | %s | %s | %s | %zu | %.3g | %.2f | %s |\n", n, set.name,
                        modeName(kModes[m]), kTreeNames[w], set.rays, rays / seconds[m][w] / 1e6,
                        seconds[m][0] / seconds[m][w],
                        o.counts ? perRay(c, rays).c_str() : "- | - | -");
            if (w == 0 && o.knownHits) {
                Counts known;
                known.hitKnown = true;
                Result out;
                runWidth<true>(kOurs, b, set, kModes[m], out, &known);
                mismatch += mismatches(out, ref);
                std::printf("| %d | %s | %s | 2 (ours), hit known | %zu | - | - | %s |\n", n,
                            set.name, modeName(kModes[m]), set.rays, perRay(known, rays).c_str());
            }
            std::fflush(stdout);
        }
}

Bench makeBench(int n, const Options& o) {
    Scene scene = sphereField(*fieldLayout(o.layout, n), o.width, o.height);
    useAcceleration(Acceleration::bvh);
    // Through a cache, which keeps whole trees: a lazy tree's subtrees would
    // not be there to collapse.
    BvhCache whole;
    Bench b{prepareScene<float>(scene, &whole), {}, {}, {}};
    useAcceleration(Acceleration::automatic);
    b.wide2 = collapseBvh<2>(b.bvh());
    b.wide4 = collapseBvh<4>(b.bvh());
    b.wide8 = collapseBvh<8>(b.bvh());
    return b;
}

void runSize(int n, const Options& o, std::size_t& mismatch) {
    const Bench b = makeBench(n, o);
    std::printf(
        "\nN = %d: binary %zu nodes (depth %d), 4-wide %zu (depth %d), "
        "8-wide %zu (depth %d); %zu leaf spheres, %zu outside the tree\n",
        n, b.bvh().nodes.size(), b.bvh().depth, b.wide4.nodes.size(), b.wide4.depth,
        b.wide8.nodes.size(), b.wide8.depth, b.bvh().leafSpheres.size(), b.bvh().direct.size());
    const RaySet camera = cameraRays(b, o.rowStep);
    const RaySet reflect = reflectRays(b, camera);
    std::vector<RaySet> sets = {camera, reflect, randomRays(o.random)};
    if (o.blocks) {
        const RaySet blocks = blockRays(b, o.blocks);
        RaySet reflectBlocks = reflectRays(b, blocks);
        reflectBlocks.name = "reflect, blocks";
        sets.push_back(blocks);
        sets.push_back(reflectBlocks);
    }
    if (o.regroup) {
        RaySet reflect2 = reflectRays(b, reflect);
        reflect2.name = "reflect2";
        sets.push_back(regroup(reflect, "reflect, regrouped", o.regroup));
        sets.push_back(reflect2);
        sets.push_back(regroup(reflect2, "reflect2, regrouped", o.regroup));
        sets.push_back(regroup(sets[2], "random, regrouped", o.regroup));
    }
    CALLGRIND_START_INSTRUMENTATION;
    for (const RaySet& set : sets) printSet(b, set, o, n, mismatch);
}

}  // namespace

int main(int argc, char** argv) {
    const Options o = parseOptions(argc, argv);
    std::printf(
        "bench_node_width: %dx%d, every %d-th row, %d random rays, %d reps, "
        "%d float lanes, 1 thread\n",
        o.width, o.height, o.rowStep, o.random, o.reps, kLanes);
    std::printf(
        "| N | set | mode | width | rays | Mrays/s | speed / ours | nodes/ray | boxes/ray | "
        "spheres/ray |\n|---|---|---|---|---|---|---|---|---|---|\n");
    std::size_t mismatch = 0;
    for (const int n : o.sizes) runSize(n, o, mismatch);
    std::printf("\nmismatches (t or sphere differing from the binary packets'): %zu\n", mismatch);
    return mismatch == 0 ? 0 : 1;
}
