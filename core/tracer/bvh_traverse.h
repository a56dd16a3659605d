// Packets of rays through a SphereBvh (bvh.h): the nearest hit and the shadow
// transmittance of ray_packet.h, from the spheres whose boxes a ray meets.
//
// Same image as brute force, bit for bit (tests/core/test_bvh.cpp):
//  * every sphere a ray is tested against goes through intersectPacket() with
//    the formulas of packetClosestHits() and packetTransmittance(); a lane's
//    result does not depend on which other lanes are active;
//  * the nearest hit is the least (t, sphere index), which is what brute
//    force's strict "t < best" in index order keeps, whatever order the tree
//    visits the spheres in;
//  * transmittance multiplies the crossed spheres' transparencies in index
//    order, as brute force does (a product rounds differently in another
//    order), and stops early only at an opaque sphere, where it is 0 either way;
//  * a box never drops a sphere whose test would report a hit (kBvhSlack below).
//
// Lanes go through the tree together, masked as they leave the boxes: every
// lane of reflected, refracted and shadow packets alone through the tree took
// 1.7 to 3 times as long (docs/design/acceleration.md), as a box or sphere test
// costs one vector operation however few lanes it serves. But in a cloud of
// balls the bounces scatter, and most nodes are entered by one lane alone
// (59 % on the inside field): that lane then walks on by itself, testing both
// children of a node in one operation (childrenMet()) and every sphere of a
// leaf in one (leaf_one_ray.h).
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "tracer/bvh.h"
#include "tracer/bvh_slabs.h"
#include "tracer/isa_namespace.h"
#include "tracer/leaf_one_ray.h"
#include "tracer/light_buffer.h"
#include "tracer/ray_packet.h"
#include "tracer/simd.h"
#include "tracer/sphere_set.h"

namespace whitted {

inline namespace WHITTED_ISA_NAMESPACE {

// A node some lanes are yet to visit, with their entry distances into its box.
template <typename T>
struct BvhVisit {
    typename Walk<T>::type entry;
    unsigned lanes;
    int node;
};

// traverseBvh() for one lane, from `node`, whose box its ray meets: the same
// walk, but testing both children of a node in one go (childrenMet()). Returns
// the lanes the leaves left looking, as leaf() does.
template <typename T, typename Leaf, typename Inner>
inline unsigned walkOneLane(const SphereSet<T>& spheres, const SphereBvh<T>& bvh,
                            const PacketSlabs<T>& slabs, const typename Simd<T>::type& limit,
                            int lane, int node, Leaf& leaf, Inner& inner) {
    const LaneSlabs<T> ray = laneSlabs(slabs, lane);
    const unsigned bit = 1u << lane;
    struct Visit {
        typename Walk<T>::scalar entry;
        int node;
    };
    Visit stack[kMaxBvhDepth + 1];
    int top = 0;
    unsigned looking = ~0u;
    for (;;) {
        const BvhNode& n = bvh.nodes[node];
        if (n.count == kLazyNode) {
            node = lazyJobRoot(bvh, n.first, spheres);
            continue;
        }
        if (n.count > 0) {
            looking &= leaf(n, bit);
            if (!(looking & bit)) return looking;
        } else {
            inner();
            typename Walk<T>::scalar entry[2];
            const unsigned met = childrenMet(&bvh.nodes[n.first], ray, limit[lane], entry);
            if (met) {
                const int near = met == 2 || (met == 3 && entry[1] < entry[0]) ? 1 : 0;
                if (met == 3) stack[top++] = {entry[1 - near], n.first + 1 - near};
                node = n.first + near;
                continue;
            }
        }
        do {
            if (top == 0) return looking;
            --top;
        } while (stack[top].entry > limit[lane]);
        node = stack[top].node;
    }
}

// Visits the leaves whose boxes the lanes' rays meet within [0, limit],
// building a lazy tree's subtrees as the lanes enter them (from `spheres`).
// leaf(node, lanes) returns a mask of the lanes still looking; `limit` may
// shrink meanwhile. inner() is called at each inner node entered (for
// benchmarks/bench_node_width.cpp's counts; nothing in a render).
//
// Both children's boxes are tested when their parent is entered (they lie
// side by side in memory), and a child no lane meets is never stacked. The
// nearer child, by the entry distance of the packet's lowest lane, is visited
// first; the farther one waits with its lanes' entry distances, and those
// lanes whose nearest hit has come closer meanwhile are dropped when it is
// taken up. A lane passes exactly when boxLanes() at that moment would pass it.
template <typename T, typename Leaf, typename Inner = void (*)()>
inline void traverseBvh(
    const SphereSet<T>& spheres, const SphereBvh<T>& bvh, const PacketSlabs<T>& slabs,
    const typename Simd<T>::type& limit, unsigned lanes, Leaf&& leaf, Inner&& inner = [] {}) {
    using V = typename Walk<T>::type;
    BvhVisit<T> stack[kMaxBvhDepth + 1];  // a path's far children: at most its depth
    int top = 0;
    V entry;
    unsigned in = boxLanes(bvh.nodes[0], slabs, limit, lanes, entry);
    int node = 0;
    for (;;) {
        const BvhNode& n = bvh.nodes[node];
        if (in && n.count > 0) {
            lanes &= leaf(n, in);
            if (!lanes) return;
            in = 0;
        }
        if (in && n.count == kLazyNode) {
            node = lazyJobRoot(bvh, n.first, spheres);  // a root with the same box
            continue;
        }
        if (in && !(in & (in - 1))) {
            lanes &= walkOneLane(spheres, bvh, slabs, limit, __builtin_ctz(in), node, leaf, inner);
            if (!lanes) return;
            in = 0;
        }
        if (in) {
            inner();
            V entries[2];
            const unsigned inChild[2] = {
                boxLanes(bvh.nodes[n.first], slabs, limit, in, entries[0]),
                boxLanes(bvh.nodes[n.first + 1], slabs, limit, in, entries[1])};
            const int lead = __builtin_ctz(in);
            const auto key = [&](int c) {
                return (inChild[c] >> lead) & 1u
                           ? entries[c][lead]
                           : std::numeric_limits<typename Walk<T>::scalar>::infinity();
            };
            const int near = inChild[0] == 0 || (inChild[1] != 0 && key(1) < key(0)) ? 1 : 0;
            const int far = 1 - near;
            if (inChild[far]) stack[top++] = {entries[far], inChild[far], n.first + far};
            in = inChild[near];
            node = n.first + near;
            if (in) continue;
        }
        // Take up a waiting node, for its lanes still looking and not yet
        // nearer to a hit than to its box.
        do {
            if (top == 0) return;
            const BvhVisit<T>& v = stack[--top];
            in = v.lanes & lanes & ~laneBits(lanesAs<typename Simd<T>::type>(v.entry) > limit);
            node = v.node;
        } while (!in);
    }
}

// Lanes of `lanes` whose ray goes into sphere k (its own).
template <typename T>
inline unsigned lanesInto(const RayPacket<T>& r, int k, unsigned lanes) {
    return laneBits((r.originSphere == T(k)) & r.intoOrigin) & lanes;
}

// The sphere's candidate for the nearest hit of each of `lanes`, by
// packetClosestHits()'s rules; ties go to the lower index, so the outcome does
// not depend on the order spheres come in.
template <typename T>
inline void closestUpdate(const SphereSet<T>& spheres, const LeafSphere<T>& sphere,
                          const RayPacket<T>& r, unsigned lanes, typename Simd<T>::type& tBest,
                          typename Simd<T>::type& kBest) {
    using V = typename Simd<T>::type;
    const int k = sphere.index;
    const PacketRoots<T> roots = intersectPacket(spheres, sphere, r, lanes);
    const auto inward = roots.self & r.intoOrigin & maskFromBits<T>(lanes);
    if (!roots.valid && !laneBits(inward)) return;
    const auto exits = roots.hit & (roots.tFar > T(0));
    const V tInward = exits ? roots.tFar : V{} + std::numeric_limits<T>::min();
    const V t = inward ? tInward : (roots.tNear > T(0) ? roots.tNear : roots.tFar);
    const V kk = V{} + T(k);
    const auto take =
        (roots.hit | inward) & (t > T(0)) & ((t < tBest) | ((t == tBest) & (kk < kBest)));
    tBest = take ? t : tBest;
    kBest = take ? kk : kBest;
}

// The start of bvhClosestHits(): tBest and kBest set, the rays' own spheres
// and the spheres kept out of the tree tested. False when nothing is left to
// do: some origin lies beyond the tree's reach (then every sphere has been
// tested, by brute force), or the tree is empty.
template <typename T>
inline bool bvhClosestStart(const SphereSet<T>& spheres, const SphereBvh<T>& bvh,
                            const RayPacket<T>& r, const PacketSlabs<T>& slabs,
                            typename Simd<T>::type& tBest, typename Simd<T>::type& kBest) {
    using V = typename Simd<T>::type;
    if ((laneBits(slabs.reach < kBvhOriginReach<T>) & r.active) != r.active) {
        packetClosestHits(spheres, r, tBest, kBest);
        return false;
    }
    tBest = V{} + std::numeric_limits<T>::infinity();
    kBest = V{} - T(1);
    // A ray going into its own sphere meets it even where rounding says its
    // line misses (the exit at the origin): that sphere first, whatever its box.
    unsigned into = laneBits(r.intoOrigin & maskFromBits<T>(r.active));
    while (into) {
        const int k = static_cast<int>(r.originSphere[__builtin_ctz(into)]);
        const unsigned lanes = lanesInto(r, k, into);
        closestUpdate(spheres, spheres.leafSphere(k), r, lanes, tBest, kBest);
        into &= ~lanes;
    }
    // The huge spheres next: a floor's hit shortens every ray before the tree.
    for (const std::int32_t k : bvh.direct)
        closestUpdate(spheres, spheres.leafSphere(k), r, r.active, tBest, kBest);
    return !bvh.nodes.empty();
}

// packetClosestHits() through the tree. Kept out of line, as is
// bvhTransmittance(): inlined into the kernel's packet loop beside the
// brute-force path, it cost the seed's render (brute force) 0.5% more
// instructions; out of line, the 100k field's render costs 2% more
// instructions and 15% fewer L1 misses (callgrind, docs/design/acceleration.md).
template <typename T>
__attribute__((noinline)) void bvhClosestHits(const SphereSet<T>& spheres, const SphereBvh<T>& bvh,
                                              const RayPacket<T>& r, typename Simd<T>::type& tBest,
                                              typename Simd<T>::type& kBest) {
    const PacketSlabs<T> slabs = packetSlabs(r, treeReach(bvh));
    if (!bvhClosestStart(spheres, bvh, r, slabs, tBest, kBest)) return;
    // Testing a ray's own sphere again changes nothing: its (t, k) is already kept.
    auto leaf = [&](const BvhNode& node, unsigned lanes) {
        // One lane: the leaf's spheres a vector's worth at a time. This loop and
        // the shadow leaf's are written out: a shared helper taking a lambda
        // stayed out of line and cost the inside field 3 to 4 %.
        if (!(lanes & (lanes - 1)) && node.count > 1) {
            const int lane = __builtin_ctz(lanes);
            T t = tBest[lane], k = kBest[lane];
            const int end = node.first + node.count;
            for (int i = node.first; i < end; i += RayPacket<T>::kWidth) {
                const int n = end - i < RayPacket<T>::kWidth ? end - i : RayPacket<T>::kWidth;
                closestUpdateOneRay(spheres, sphereLanes(&bvh.leafSpheres[i], n), r, lane, t, k);
            }
            tBest[lane] = t;
            kBest[lane] = k;
            return ~0u;
        }
        for (int i = node.first; i < node.first + node.count; ++i)
            closestUpdate(spheres, bvh.leafSpheres[i], r, lanes, tBest, kBest);
        return ~0u;
    };
    traverseBvh(spheres, bvh, slabs, tBest, r.active, leaf);
}

// The spheres each lane's shadow ray crosses, to be multiplied in index order.
template <typename T>
struct Occluders {
    static constexpr int kCapacity = 32;  // more, and the lane is redone by brute force
    int count[RayPacket<T>::kWidth] = {};
    std::int32_t sphere[RayPacket<T>::kWidth][kCapacity];
    unsigned opaque = 0;    // lanes that cross an opaque sphere: S = 0
    unsigned overflow = 0;  // lanes that crossed more than kCapacity transparent spheres

    void add(unsigned lanes, int k, T transparency) {
        if (transparency == T(0)) {
            opaque |= lanes;
            return;
        }
        if (transparency == T(1)) return;  // s * 1 == s exactly
        for (; lanes; lanes &= lanes - 1) {
            const int l = __builtin_ctz(lanes);
            if (count[l] < kCapacity)
                sphere[l][count[l]++] = k;
            else
                overflow |= 1u << l;
        }
    }
};

// The sphere's part in each lane's transmittance, by packetTransmittance()'s rules.
template <typename T>
inline void shadowUpdate(const SphereSet<T>& spheres, const std::vector<T>& transparency,
                         const LeafSphere<T>& sphere, const RayPacket<T>& r,
                         const typename Simd<T>::type& distance, unsigned lanes,
                         Occluders<T>& out) {
    const int k = sphere.index;
    const PacketRoots<T> roots = intersectPacket(spheres, sphere, r, lanes);
    const auto inward = roots.self & r.intoOrigin & maskFromBits<T>(lanes);
    if (!roots.valid && !laneBits(inward)) return;
    const auto exits = roots.hit & (roots.tFar > T(0));
    const auto crossesOwn = exits ? roots.tFar < distance : distance > T(0);
    const auto crossesOther = ((roots.tNear > T(0)) & (roots.tNear < distance)) |
                              ((roots.tFar > T(0)) & (roots.tFar < distance));
    const auto take = inward ? crossesOwn : crossesOther & roots.hit;
    if (const unsigned bits = laneBits(take) & lanes) out.add(bits, k, transparency[k]);
}

// Insertion sort of a lane's few occluders. Not std::sort: its helpers would be
// instantiated outside this instruction set's namespace (isa_namespace.h).
inline void sortIndices(std::int32_t* first, std::int32_t* last) {
    for (std::int32_t* i = first + (first != last); i < last; ++i) {
        const std::int32_t v = *i;
        std::int32_t* j = i;
        for (; j > first && j[-1] > v; --j) *j = j[-1];
        *j = v;
    }
}

// The index of the cell of `buffer` that a shadow ray with direction d (towards
// the light) falls in; -1 where no sphere of the buffer's lies that way.
template <typename T>
inline int lightBufferCell(const LightBuffer& buffer, T dx, T dy, T dz) {
    // Seen from the light the ray's direction is -d.
    const double x = -double(dx), y = -double(dy), z = -double(dz);
    const double ax = std::fabs(x), ay = std::fabs(y), az = std::fabs(z);
    int axis;
    double m, u, v;
    if (ax >= ay && ax >= az) {
        axis = 0, m = x, u = y, v = z;
    } else if (ay >= az) {
        axis = 1, m = y, u = z, v = x;
    } else {
        axis = 2, m = z, u = x, v = y;
    }
    const LightBufferFace& face = buffer.faces[2 * axis + (m < 0)];
    const double across = std::fabs(m);
    const double i = std::floor((u / across - face.u0) * face.cellsPerU);
    const double j = std::floor((v / across - face.v0) * face.cellsPerV);
    if (!(i >= 0 && i < face.nu && j >= 0 && j < face.nv)) return -1;
    return face.firstCell + int(j) * face.nu + int(i);
}

// The lanes of `lanes` whose shadow rays the light's buffer answers, their
// cells' spheres tested into `found` by shadowUpdate()'s rules (a lane's own
// sphere, when it goes into it, left out: counted before): every lane but
// those whose cell lists too many spheres for the tree to be spared. Lanes
// that share a cell test its spheres together, a vector operation a sphere;
// a lane alone tests a vector's worth of them at once.
template <typename T>
inline unsigned bufferTransmittance(const SphereSet<T>& spheres, const std::vector<T>& transparency,
                                    const LightBuffer& buffer, const RayPacket<T>& r,
                                    const typename Simd<T>::type& distance, unsigned lanes,
                                    unsigned goingIn, Occluders<T>& found) {
    int cellOf[RayPacket<T>::kWidth];
    for (unsigned open = lanes; open; open &= open - 1) {
        const int lane = __builtin_ctz(open);
        cellOf[lane] = lightBufferCell(buffer, r.dx[lane], r.dy[lane], r.dz[lane]);
    }
    unsigned answered = 0;
    for (unsigned rest = lanes; rest;) {
        const int c = cellOf[__builtin_ctz(rest)];
        unsigned group = 0;
        for (unsigned bits = rest; bits; bits &= bits - 1)
            if (cellOf[__builtin_ctz(bits)] == c) group |= 1u << __builtin_ctz(bits);
        rest &= ~group;
        const LightBufferCell cell = c < 0 ? LightBufferCell{} : buffer.cells[std::size_t(c)];
        if (cell.count == LightBufferCell::kThroughTree) continue;
        answered |= group;
        const int end = int(cell.first + cell.count);
        if (!(group & (group - 1))) {
            const int lane = __builtin_ctz(group);
            for (int i = int(cell.first); i < end && !(found.opaque & group);
                 i += RayPacket<T>::kWidth) {
                const int n = end - i < RayPacket<T>::kWidth ? end - i : RayPacket<T>::kWidth;
                shadowUpdateOneRay(spheres, transparency,
                                   sphereLanesOf(spheres, &buffer.spheres[i], n), r, lane,
                                   distance[lane], found);
            }
            continue;
        }
        for (int i = int(cell.first); i < end; ++i) {
            const unsigned in = group & ~found.opaque;
            if (!in) break;
            const std::int32_t k = buffer.spheres[std::size_t(i)];
            const unsigned test = goingIn ? in & ~lanesInto(r, k, goingIn) : in;
            if (test)
                shadowUpdate(spheres, transparency, spheres.leafSphere(k), r, distance, test,
                             found);
        }
    }
    return answered;
}

// packetTransmittance() through the tree, or the light's buffer where it has
// one; `loneLeaves` counts the walk's leaf visits by a lane alone.
template <typename T>
__attribute__((noinline)) typename Simd<T>::type bvhTransmittance(
    const SphereSet<T>& spheres, const std::vector<T>& transparency, const SphereBvh<T>& bvh,
    const RayPacket<T>& r, const typename Simd<T>::type& distance, unsigned lanes,
    const LightBuffer* buffer = nullptr, std::uint64_t* loneLeaves = nullptr) {
    using V = typename Simd<T>::type;
    const PacketSlabs<T> slabs = packetSlabs(r, treeReach(bvh));
    if ((laneBits(slabs.reach < kBvhOriginReach<T>) & lanes) != lanes)
        return packetTransmittance(spheres, transparency, r, distance, lanes);
    Occluders<T> found;
    unsigned into = laneBits(r.intoOrigin & maskFromBits<T>(lanes));
    const unsigned goingIn = into;
    while (into) {
        const int k = static_cast<int>(r.originSphere[__builtin_ctz(into)]);
        const unsigned own = lanesInto(r, k, into);
        shadowUpdate(spheres, transparency, spheres.leafSphere(k), r, distance, own, found);
        into &= ~own;
    }
    for (const std::int32_t k : bvh.direct)
        if (const unsigned open = lanes & ~found.opaque)
            shadowUpdate(spheres, transparency, spheres.leafSphere(k), r, distance,
                         goingIn ? open & ~lanesInto(r, k, goingIn) : open, found);
    std::uint64_t lone = 0;
    auto leaf = [&](const BvhNode& node, unsigned in) {
        if (!(in & (in - 1)) && node.count > 1) {
            ++lone;
            const int lane = __builtin_ctz(in);
            const int end = node.first + node.count;
            for (int i = node.first; i < end && !(found.opaque & in); i += RayPacket<T>::kWidth) {
                const int n = end - i < RayPacket<T>::kWidth ? end - i : RayPacket<T>::kWidth;
                shadowUpdateOneRay(spheres, transparency, sphereLanes(&bvh.leafSpheres[i], n), r,
                                   lane, distance[lane], found);
            }
            return ~found.opaque;
        }
        for (int i = node.first; i < node.first + node.count && in; ++i) {
            const LeafSphere<T>& sphere = bvh.leafSpheres[i];
            // Its own sphere was counted above; once is all.
            const unsigned test = goingIn ? in & ~lanesInto(r, sphere.index, goingIn) : in;
            if (test) shadowUpdate(spheres, transparency, sphere, r, distance, test, found);
            in &= ~found.opaque;
        }
        return ~found.opaque;
    };
    unsigned viaTree = lanes & ~found.opaque;
    if (buffer)
        viaTree &= ~bufferTransmittance(spheres, transparency, *buffer, r, distance, viaTree,
                                        goingIn, found);
    if (!bvh.nodes.empty() && viaTree) traverseBvh(spheres, bvh, slabs, distance, viaTree, leaf);
    if (loneLeaves) *loneLeaves += lone;
    V s = V{} + T(1);
    for (unsigned open = lanes & ~found.opaque & ~found.overflow; open; open &= open - 1) {
        const int l = __builtin_ctz(open);
        std::int32_t* first = found.sphere[l];
        std::int32_t* last = first + found.count[l];
        sortIndices(first, last);
        T product = T(1);
        for (const std::int32_t* k = first; k != last; ++k) product = product * transparency[*k];
        s[l] = product;
    }
    for (unsigned bits = found.opaque & lanes; bits; bits &= bits - 1)
        s[__builtin_ctz(bits)] = T(0);
    if (const unsigned redo = found.overflow & ~found.opaque & lanes) {
        const V brute = packetTransmittance(spheres, transparency, r, distance, redo);
        for (unsigned bits = redo; bits; bits &= bits - 1) {
            const int l = __builtin_ctz(bits);
            s[l] = brute[l];
        }
    }
    return s;
}

// The nearest hits and the transmittance of a packet, through the tree when
// the scene has one (bvh non-null), else by testing every sphere.
template <typename T>
inline void sceneClosestHits(const SphereSet<T>& spheres, const SphereBvh<T>* bvh,
                             const RayPacket<T>& r, typename Simd<T>::type& tBest,
                             typename Simd<T>::type& kBest) {
    if (bvh)
        bvhClosestHits(spheres, *bvh, r, tBest, kBest);
    else
        packetClosestHits(spheres, r, tBest, kBest);
}

template <typename T>
inline typename Simd<T>::type sceneTransmittance(
    const SphereSet<T>& spheres, const std::vector<T>& transparency, const SphereBvh<T>* bvh,
    const RayPacket<T>& r, const typename Simd<T>::type& distance, unsigned lanes,
    const ShadowCone<T>* cones = nullptr, const LightBuffer* buffer = nullptr,
    std::uint64_t* loneLeaves = nullptr) {
    return bvh ? bvhTransmittance(spheres, transparency, *bvh, r, distance, lanes, buffer,
                                  loneLeaves)
               : packetTransmittance(spheres, transparency, r, distance, lanes, cones);
}

}  // namespace WHITTED_ISA_NAMESPACE
}  // namespace whitted
