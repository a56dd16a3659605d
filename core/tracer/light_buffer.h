// A point light's view of the tree's spheres (a light buffer): the directions
// around the light cut into cells on the six faces of a cube, each cell listing
// the spheres whose shadow cone (shadow_cones.h) reaches into it. A shadow ray's
// direction picks one cell, and the ray is tested against that cell's spheres
// instead of walking the tree: where the light looks down on a cloud of balls, a
// cell lists about as many spheres as a line from the light crosses, a handful,
// while a walk to the same answer enters some twenty nodes one after another. A
// cell that would list too many sends its rays through the tree. Made for a
// pass whose rays pay for it (kLightBufferRaysPerSphere), outside the per-ISA
// kernels, as shadow_cones.h.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "tracer/sphere_set.h"

namespace whitted {

// A light's buffer is made during a render, on one thread, once that
// thread's first kLightBufferProbe shadow rays show the walks scattered: at
// least kLoneLeavesPerShadowRay of their leaf visits, on average, made by a
// lane alone. Coherent shadow packets walk the tree as cheaply as they would
// test a cell's spheres, and there a buffer would only cost its making
// (docs/design/acceleration.md). Only in a pass of at least
// kLightBufferRaysPerSphere camera samples a sphere: the making takes about
// a tenth of a microsecond a sphere.
inline constexpr std::uint64_t kLightBufferProbe = 16384;
inline constexpr double kLoneLeavesPerShadowRay = 0.2;
inline constexpr double kLightBufferRaysPerSphere = 4.0;

// A face of the cube around the light: the directions d whose largest
// component in absolute value is d[axis], with the face's sign. Its cells cover
// the rectangle of (u, v) = (d[(axis + 1) % 3], d[(axis + 2) % 3]) / |d[axis]|
// that the spheres' cones reach, nu by nv of them; no sphere is seen from the
// light in a direction outside it.
struct LightBufferFace {
    double u0 = 0, v0 = 0;  // the rectangle's low corner
    double cellsPerU = 0, cellsPerV = 0;
    int nu = 0, nv = 0;  // 0: no sphere is seen through this face
    int firstCell = 0;
};

struct LightBufferCell {
    // kThroughTree: too many spheres to test one by one; the tree instead.
    static constexpr std::uint32_t kThroughTree = ~0u;
    std::uint32_t first = 0, count = 0;  // LightBuffer::spheres[first, first + count)
};

struct LightBuffer {
    LightBufferFace faces[6];  // +x, -x, +y, -y, +z, -z
    std::vector<LightBufferCell> cells;
    std::vector<std::int32_t> spheres;  // each cell's, the same for any number of threads
};

// Where a light's buffer is put once made, for the render's threads to find.
class LightBufferSlot {
  public:
    // The buffer, once made; null before, and when it was not.
    const LightBuffer* ready() const { return ready_.load(std::memory_order_acquire); }
    // Whether some thread has taken the decision to make it or not.
    bool claimed() const { return claimed_.load(std::memory_order_relaxed); }
    // True for the first caller only: that one decides.
    bool claim() { return !claimed_.exchange(true, std::memory_order_relaxed); }
    // By the caller that claimed the slot.
    void publish(std::shared_ptr<const LightBuffer> buffer) {
        owned_ = std::move(buffer);
        ready_.store(owned_.get(), std::memory_order_release);
    }

  private:
    std::atomic<const LightBuffer*> ready_{nullptr};
    std::atomic<bool> claimed_{false};
    std::shared_ptr<const LightBuffer> owned_;
};

// The buffer of the light at `light` for the spheres of `spheres` but those in
// `direct` (which every ray tests anyway), built on up to `threads` threads
// (0: all cores); null where a sphere lies so near the light that its cone is
// too wide, or where the cells would list more spheres than memory should hold.
template <typename T>
std::shared_ptr<const LightBuffer> lightBuffer(const Vec<T>& light, const SphereSet<T>& spheres,
                                               std::span<const std::int32_t> direct, int threads);

}  // namespace whitted
