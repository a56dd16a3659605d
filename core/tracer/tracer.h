// The Whitted tracer (SPEC §3), one template for float and double.
//
// The tracing functions below run in the kernel built for the widest
// instruction set the CPU has (kernel_dispatch.h, tracer_kernel.cpp).
//
// A render first compiles the Scene into a PreparedScene<T>: numbers in T,
// material names resolved to indices, spheres laid out for the hit loop, and
// flags saying which kinds of secondary rays the scene can use at all.
//
// Self-intersection policy (the only one; no epsilons anywhere): a secondary ray
// remembers the sphere it leaves. A sphere is convex, so a ray leaving it outwards
// can never hit it again and skips it; a ray going into it can only hit its far
// side and takes the far root. This is exact and independent of scale.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "scene/scene.h"
#include "tracer/bvh.h"
#include "tracer/camera.h"
#include "tracer/light_buffer.h"
#include "tracer/sampling.h"
#include "tracer/screen_boxes.h"
#include "tracer/shadow_cones.h"
#include "tracer/sphere_intersect.h"
#include "tracer/sphere_set.h"

namespace whitted {

// Rays traced, by kind. Shadow rays count once per (hit, light) actually tested.
struct RayCounts {
    std::uint64_t camera = 0;
    std::uint64_t shadow = 0;
    std::uint64_t reflection = 0;
    std::uint64_t refraction = 0;
    // Not rays: the shadow walks' visits to a leaf by one lane alone, which
    // tell how scattered the shadow rays are (kLoneLeavesPerShadowRay).
    std::uint64_t shadowLoneLeaves = 0;
    std::uint64_t total() const { return camera + shadow + reflection + refraction; }
    RayCounts& operator+=(const RayCounts& o) {
        camera += o.camera;
        shadow += o.shadow;
        reflection += o.reflection;
        refraction += o.refraction;
        shadowLoneLeaves += o.shadowLoneLeaves;
        return *this;
    }
};

template <typename T>
struct Ray {
    Vec<T> origin;
    Vec<T> dir;               // unit length
    int originSphere = -1;    // the sphere the ray leaves, -1 for camera rays
    bool intoOrigin = false;  // the ray goes into originSphere (refraction, inner reflection)
    bool fromCamera = false;  // origin is the camera position: reuse its cached offsets
};

template <typename T>
struct PreparedMaterial {
    Vec<T> diffuse;
    Vec<T> checkerColor;
    T checkerInvSize = 0;  // 1 / checker size; 0 means no checker
    // The size itself as hi + lo: the steep-axis cell divides by it, since
    // multiplying by an inexact 1/size (1/50 in a seed scaled by 100) puts the
    // floor's top, exactly one cell down, on the wrong side of the boundary.
    T checkerSize = 0, checkerSizeLo = 0;
    // The frame origin in checker cells is whole + fraction per axis: the
    // fraction in [0, 1) as a two-term value (the steep-axis cell needs it to
    // about eps^2), and whether whole is odd (0 or 1).
    Vec<T> checkerFrameFraction{T(0)}, checkerFrameFractionLo{T(0)}, checkerFrameParity{T(0)};
    T specular = 0, shininess = 0, reflectivity = 0, transparency = 0, ior = 1;
    int integerShininess = -1;  // shininess when it is a small whole number, else -1
    bool lit = false;           // diffuse or specular can be non-zero: shadow rays are useful
};

template <typename T>
struct PreparedLight {
    Vec<T> position;
    Vec<T> color;  // colour * intensity
    // Without the tree, each sphere's cone from this light: a shadow ray is
    // tested against the spheres whose cone holds its direction.
    std::vector<ShadowCone<T>> cones;
    // With the tree, in a pass that may pay for it, where this light's buffer
    // goes once made (addLightBufferSlots()); null otherwise.
    std::shared_ptr<LightBufferSlot> buffer;
};

// Positions in a prepared scene are relative to frameOrigin (world = frameOrigin +
// prepared), so that T never has to hold a large coordinate the picture does not need.
template <typename T>
struct PreparedScene {
    Vec3 frameOrigin{0.0};  // in scene (world) coordinates, double
    CameraBasis<T> camera;
    SphereSet<T> spheres;         // geometry, in scene order
    std::vector<int> material;    // per sphere: index into materials
    std::vector<T> transparency;  // per sphere, from its material: the shadow-ray factor
    // Which spheres a ray is tested against: all of them, or those the tree
    // finds near it (useBvh). Either way the same image, bit for bit.
    std::shared_ptr<const SphereBvh<T>> bvh;  // shared with a BvhCache, when one is kept
    bool useBvh = false;
    // Without the tree, where each of the first spheres can be seen: a packet
    // of camera rays tests only the spheres whose box it meets.
    std::vector<ScreenBox> screenBoxes;
    std::vector<PreparedMaterial<T>> materials;
    std::vector<PreparedLight<T>> lights;
    Vec<T> background, ambient;
    int maxDepth = 0;
    // A reflected or refracted ray whose path passes on less than this weight
    // (the product of kr and kt along it) is not traced. 0 in every render
    // SPEC describes; a planning render that looks deep sets it
    // (RenderOptions::pruneBelowWeight).
    T pruneBelow = 0;
    int samplesPerPixel = 1;
    SamplePattern pattern = samplePattern(1);  // samplePattern(samplesPerPixel)
    // Samples from progressiveSample(), whose every power-of-two prefix is
    // stratified, rather than from subPixelSample()'s pattern for exactly
    // samplesPerPixel: for renders whose tiles stop at counts of their own.
    bool openEndedSamples = false;
    int width = 1, height = 1;
};

// How prepareScene() lets rays find their spheres. Automatic: a BVH above
// kBvhCrossover spheres, every sphere tested below it (the seed's four).
enum class Acceleration { automatic, bruteForce, bvh };
inline constexpr int kBvhCrossover = 16;

// From now on prepare scenes with this choice (tests, benchmarks); automatic
// goes back to what the environment variable WHITTED_ACCEL says (auto, brute
// or bvh; read once), or the automatic choice when it is unset.
void useAcceleration(Acceleration choice);
// The choice prepareScene() makes for a scene of `spheres` spheres. Throws
// std::runtime_error when WHITTED_ACCEL holds anything else.
bool bvhChosen(int spheres);

// The scene must be valid (validateScene); width, height, depth and samples
// come from scene.render. Builds the sphere BVH when bvhChosen() says so, on
// up to `threads` threads (0: every core this process may run on), so that a
// render asked for one thread prepares on one too. `sceneRead`, when set, is
// called once the scene has been read, before the tree's build or refit, which
// work from the prepared copies: its owner may change or free it from then on.
template <typename T>
PreparedScene<T> prepareScene(const Scene& scene, BvhCache* bvhCache = nullptr, int threads = 0,
                              const std::function<void()>& sceneRead = {});

// Gives each light of a scene prepared with the tree a slot for its buffer
// (light_buffer.h), which the render's threads fill when their shadow rays
// show it pays (considerLightBuffer()). The images stay the same to the bit:
// a buffer only spares shadow rays the walk.
template <typename T>
void addLightBufferSlots(PreparedScene<T>& s);

// Makes each light's buffer now, on up to `threads` threads (0: all cores),
// where one can be made: for tests and benchmarks.
template <typename T>
void addLightBuffers(PreparedScene<T>& s, int threads = 0);

// Called by a render thread after a shadow packet of `light` while its slot
// is unclaimed: makes the buffer, on this thread, once `counts` (the
// thread's own) show that the shadow rays are scattered enough.
template <typename T>
void considerLightBuffer(const PreparedScene<T>& s, const PreparedLight<T>& light,
                         const RayCounts& counts);

template <typename T>
struct Hit {
    T t;         // distance along the ray, > 0
    int sphere;  // index into the scene's spheres
};

// The nearest hit with t in (0, tMax), honouring the self-intersection policy.
template <typename T>
std::optional<Hit<T>> closestHit(const PreparedScene<T>& s, const Ray<T>& ray,
                                 T tMax = std::numeric_limits<T>::infinity());

// Radiance along a ray at the given depth (0 for camera rays).
template <typename T>
Vec<T> traceRay(const PreparedScene<T>& s, const Ray<T>& ray, int depth, RayCounts& counts);

// A camera sample: pixel (i, j) at sub-pixel offset (u, v) in [0,1)^2.
template <typename T>
struct CameraSample {
    int i, j;
    T u, v;
};

// Radiance for `count` camera samples (any count; they are intersected with
// the scene several rays at a time). Counts the camera rays. Each result is the
// same as tracing that sample alone.
template <typename T>
void traceCameraSamples(const PreparedScene<T>& s, const CameraSample<T>* samples, int count,
                        Vec<T>* radiance, RayCounts& counts);

// Sample n of the pixels (x0 .. x0+count-1, y .. y+rows-1): the same results
// as traceCameraSamples() with pixelSample() for each, without building the
// list. radiance holds rows * count values, row by row. A packet holds a
// block of pixels several rows tall: on a field of balls a few pixels across,
// the rays of a row's pixels parted at every leaf, and a square of them parts
// less (docs/design/acceleration.md, "Packets of pixels").
template <typename T>
void traceCameraRows(const PreparedScene<T>& s, int y, int rows, int x0, int count, int n,
                     Vec<T>* radiance, RayCounts& counts);

// traceCameraRows() of one row.
template <typename T>
void traceCameraRow(const PreparedScene<T>& s, int y, int x0, int count, int n, Vec<T>* radiance,
                    RayCounts& counts);

// Samples n0 .. n0+samples-1 of each of the pixels (x0 .. x0+pixels-1, y),
// pixel by pixel: radiance[p * samples + k] is sample n0 + k of pixel x0 + p.
// The same results as traceCameraRow() for each sample; a packet holds a
// pixel's own samples, whose rays part less than those of a row's pixels (a
// field of glass balls rendered a quarter faster at 128 samples).
template <typename T>
void traceCameraBlock(const PreparedScene<T>& s, int y, int x0, int pixels, int n0, int samples,
                      Vec<T>* radiance, RayCounts& counts);

// traceCameraRow(), and besides, for each of `depths` (ascending, none past
// the scene's max depth), the radiance the same ray has at that max depth:
// SPEC spawns no ray past the depth, so it is the sum of what each bounce
// level up to it adds, at its path's weight (equal to a render at that depth
// but for rounding). One render then gives the picture at several depths, as
// planning compares them (analysis/quality_target.cpp). atDepths holds
// count * depthCount values, pixel by pixel.
template <typename T>
void traceCameraRowAtDepths(const PreparedScene<T>& s, int y, int x0, int count, int n,
                            Vec<T>* radiance, const int* depths, int depthCount, Vec<T>* atDepths,
                            RayCounts& counts);

// One camera sample; the same result as traceCameraSamples() gives for it.
template <typename T>
Vec<T> tracePixelSample(const PreparedScene<T>& s, int i, int j, T u, T v, RayCounts& counts);

// The sample index that means the pixel's centre whatever the scene's samples
// a pixel: an adaptive render's first pass where one sample may do
// (AdaptiveSampling::centresFirst).
inline constexpr int kPixelCentre = -1;

// Sub-pixel offset of sample n of pixel (i, j) for the scene's samples_per_pixel (SPEC §4).
template <typename T>
CameraSample<T> pixelSample(const PreparedScene<T>& s, int i, int j, int n);

// Reflection of unit d about unit n.
template <typename T>
Vec<T> reflect(const Vec<T>& d, const Vec<T>& n) {
    return d - T(2) * (d.x * n.x + d.y * n.y + d.z * n.z) * n;
}

// Snell refraction of unit d through a surface whose unit normal n faces d's
// origin (dot(d, n) < 0), with eta = n_from / n_to; nothing on total internal reflection.
template <typename T>
std::optional<Vec<T>> refract(const Vec<T>& d, const Vec<T>& n, T eta) {
    const T cosi = -(d.x * n.x + d.y * n.y + d.z * n.z);
    const T k = T(1) - eta * eta * (T(1) - cosi * cosi);
    if (!(k >= T(0))) return std::nullopt;
    return glm::normalize(eta * d + (eta * cosi - std::sqrt(k)) * n);
}

}  // namespace whitted
