#include "tracer/tracer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>

#include "base/parallel_for.h"
#include "base/uninitialised_allocator.h"
#include "scene/scene_io.h"
#include "tracer/kernel_dispatch.h"
#include "tracer/renderer.h"
#include "tracer/sample_lanes.h"
#include "tracer/sampling.h"
#include "tracer/tracer_kernel.h"

namespace whitted {

namespace {

// Colours, intensities and specular weights as T, at most sqrt(largest T) / 16
// (1.1e18 in float, 8e152 in double): a product of two of them, and the sums of
// a few such products, stay finite, so no infinity can meet a zero and make a
// NaN (a light of intensity 1e300 on a material whose red is 0).
template <typename T>
T boundedInput(double v) {
    static const double kLargest = std::sqrt(double(std::numeric_limits<T>::max())) / 16.0;
    return T(std::min(v, kLargest));
}

template <typename T>
Vec<T> boundedInput(const Vec3& v) {
    return {boundedInput<T>(v.x), boundedInput<T>(v.y), boundedInput<T>(v.z)};
}

std::atomic<Acceleration> forcedAcceleration{Acceleration::automatic};

Acceleration environmentAcceleration() {
    static const Acceleration choice = [] {
        const char* v = std::getenv("WHITTED_ACCEL");
        const std::string name = v ? v : "";
        if (name.empty() || name == "auto") return Acceleration::automatic;
        if (name == "brute") return Acceleration::bruteForce;
        if (name == "bvh") return Acceleration::bvh;
        throw std::runtime_error("WHITTED_ACCEL: unknown value '" + name +
                                 "' (auto, brute or bvh)");
    }();
    return choice;
}

// The camera position moved onto a grid of 2^-24 of the camera's distance to
// its look-at point (a power of two, so scaling the scene by one scales the
// frame with it, bit for bit). Why not the position itself: a coordinate such
// as 0.35 has all 53 bits, so a sphere's centre relative to it (the seed's
// floor: -99999.5 - 0.35) needs 70, and a float pair holds 48. What it drops
// moved the floor's top by 6e-11, more than the floor falls below the checker's
// cell boundary near where it touches it, and float coloured a pixel of every
// 640x480 seed render from the wrong cell. Relative to a point on the grid, a
// centre on the grid (-99999.5) within 2^24 distances of the camera is exact.
Vec3 frameOriginNear(const Camera& camera) {
    const double distance = glm::length(camera.lookAt - camera.position);
    if (!(distance > 0.0) || !std::isfinite(distance)) return camera.position;
    const int step = std::ilogb(distance) - 24;  // the grid is 2^step
    Vec3 origin = camera.position;
    for (int i = 0; i < 3; ++i) {
        const double steps = std::ldexp(origin[i], -step);
        if (std::isfinite(steps) && std::fabs(steps) < 0x1p52)
            origin[i] = std::ldexp(std::nearbyint(steps), step);
    }
    return origin;
}

}  // namespace

void useAcceleration(Acceleration choice) {
    forcedAcceleration = choice;
}

bool bvhChosen(int spheres) {
    Acceleration choice = forcedAcceleration;
    if (choice == Acceleration::automatic) choice = environmentAcceleration();
    if (choice == Acceleration::automatic) return spheres > kBvhCrossover;
    return choice == Acceleration::bvh;
}

// A material in the tracer's precision, its checker placed in the frame
// centred on `frameOrigin`.
template <typename T>
PreparedMaterial<T> prepareMaterial(const Material& m, const Vec3& frameOrigin) {
    PreparedMaterial<T> pm;
    pm.diffuse = boundedInput<T>(m.diffuse);
    if (m.checker) {
        pm.checkerColor = boundedInput<T>(m.checker->color);
        pm.checkerInvSize = T(1.0 / m.checker->size);
        const volatile T size = T(m.checker->size);  // volatile: see SphereSet::split
        pm.checkerSize = size;
        pm.checkerSizeLo = T(m.checker->size - double(pm.checkerSize));
        // floor(world / size) == floor(frameOrigin / size + prepared / size):
        // the frame origin's whole cells are kept apart, as a parity, so that
        // T adds only a fraction in [0, 1) to the cell coordinate.
        for (int i = 0; i < 3; ++i) {
            const double q = frameOrigin[i] / m.checker->size;
            const double whole = std::floor(q);
            const double fraction = q - whole;
            const volatile T hi = T(fraction);  // volatile: see SphereSet::split
            pm.checkerFrameFraction[i] = hi;
            pm.checkerFrameFractionLo[i] = T(fraction - double(hi));
            pm.checkerFrameParity[i] = T(whole - 2.0 * std::floor(whole * 0.5));
        }
    }
    pm.specular = boundedInput<T>(m.specular);
    pm.shininess = T(m.shininess);
    pm.reflectivity = T(m.reflectivity);
    pm.transparency = T(m.transparency);
    pm.ior = T(m.ior);
    if (m.shininess == std::floor(m.shininess) && m.shininess <= 1024)
        pm.integerShininess = static_cast<int>(m.shininess);
    const bool diffuseLit = m.diffuse != Vec3(0.0) || (m.checker && m.checker->color != Vec3(0.0));
    pm.lit = diffuseLit || m.specular > 0;
    return pm;
}

// Where the BVH's build reads the spheres: centres in the frame and radii,
// only when a tree is built. Not zeroed (32 MB at a million spheres, on one
// thread): every element is written.
struct BvhInput {
    std::vector<Vec3, UninitialisedAllocator<Vec3>> centres;
    std::vector<double, UninitialisedAllocator<double>> radii;
};

// The camera terms (SphereSet::cameraC) of spheres [begin, end) from `eye`, a
// SIMD vector of spheres at a time: accurateOffsetSquaredOfLanes() with the
// eye in every lane, so each term is what accurateOffsetSquared() gives it.
// One at a time they were about half of preparing a million spheres.
template <typename T>
void setCameraTerms(SphereSet<T>& spheres, const Vec<T>& eye, int begin, int end) {
    using V = typename Simd<T>::type;
    constexpr int kLanes = int(sizeof(V) / sizeof(T));
    const V o[3] = {V{} + eye[0], V{} + eye[1], V{} + eye[2]};
    int k = begin;
    for (; k + kLanes <= end; k += kLanes) {
        V c[3], cLo[3], rrHi, rrLo;
        for (int lane = 0; lane < kLanes; ++lane) {
            for (int i = 0; i < 3; ++i) {
                c[i][lane] = spheres.centre[k + lane][i];
                cLo[i][lane] = spheres.centreLo[k + lane][i];
            }
            rrHi[lane] = spheres.rrHi[k + lane];
            rrLo[lane] = spheres.rrLo[k + lane];
        }
        const V terms = accurateOffsetSquaredOfLanes(o, c, cLo, rrHi, rrLo);
        for (int lane = 0; lane < kLanes; ++lane) spheres.cameraC[k + lane] = terms[lane];
    }
    for (; k < end; ++k)
        spheres.cameraC[k] = accurateOffsetSquared(eye, spheres.centre[k], spheres.centreLo[k],
                                                   spheres.rrHi[k], spheres.rrLo[k]);
}

// Every sphere into its own place in s.spheres, s.material and
// s.transparency (and `bvh`, when sized), on up to `threads` threads: a
// million spheres took a second on one (docs/design/acceleration.md). Fewer
// than kSphereChunk stay on this thread. Throws, in validateScene()'s words,
// for a sphere whose material is missing (validated scenes never have one).
template <typename T>
void prepareSpheres(const Scene& scene, PreparedScene<T>& s, BvhInput& bvh, int threads) {
    const int count = static_cast<int>(scene.spheres.size());
    const bool forBvh = !bvh.centres.empty();
    s.spheres.resize(count);
    s.material.resize(count);
    s.transparency.resize(count);
    const auto materialIndex = materialIndices(scene);
    std::atomic<int> unknownMaterial{-1};
    forEachChunk(count, threads, [&](int, int begin, int end) {
        // Neighbouring spheres mostly share a material: the name is hashed
        // only when it differs from the one before.
        const std::string* lastName = nullptr;
        int lastMaterial = -1;
        for (int k = begin; k < end; ++k) {
            const Sphere& sp = scene.spheres[k];
            Vec3 c, cLo;  // the centre in the frame, exactly: c + cLo
            for (int i = 0; i < 3; ++i)
                exact::twoSum(sp.center[i], -s.frameOrigin[i], c[i], cLo[i]);
            s.spheres.place(k, c, cLo, sp.radius);
            if (!lastName || sp.material != *lastName) {
                const auto found = materialIndex.find(sp.material);
                if (found == materialIndex.end()) unknownMaterial = k;
                lastName = &sp.material;
                lastMaterial = found == materialIndex.end() ? 0 : found->second;
            }
            s.material[k] = lastMaterial;
            s.transparency[k] = s.materials.empty() ? T(1) : s.materials[lastMaterial].transparency;
            if (forBvh) {
                bvh.centres[k] = c;  // cLo is far inside the traversal's margin
                bvh.radii[k] = sp.radius;
            }
        }
        setCameraTerms(s.spheres, s.camera.origin, begin, end);
    });
    // Thrown on this thread, not a worker's.
    if (unknownMaterial >= 0) {
        const std::optional<SceneProblem> problem = validateScene(scene);
        throw std::invalid_argument(problem ? problem->jsonPath + ": " + problem->reason
                                            : "a sphere's material is missing");
    }
}

template <typename T>
PreparedScene<T> prepareScene(const Scene& scene, BvhCache* bvhCache, int threads,
                              const std::function<void()>& sceneRead) {
    PreparedScene<T> s;
    const RenderSettings& r = scene.render;
    // The frame is centred on the camera: what the picture needs is where things
    // are relative to the eye, which T then holds to its full precision however
    // far the scene lies from the world origin.
    s.frameOrigin = frameOriginNear(scene.camera);
    s.camera = makeCameraBasis<T>(scene.camera, r.width, r.height);
    s.camera.origin = Vec<T>(scene.camera.position - s.frameOrigin);
    s.width = r.width;
    s.height = r.height;
    s.maxDepth = r.maxDepth;
    s.samplesPerPixel = r.samplesPerPixel;
    s.pattern = samplePattern(r.samplesPerPixel);
    s.background = boundedInput<T>(scene.background);
    s.ambient = boundedInput<T>(scene.ambient);
    for (const Material& m : scene.materials)
        s.materials.push_back(prepareMaterial<T>(m, s.frameOrigin));
    for (const Light& l : scene.lights) {
        const Vec3 c = l.color * l.intensity;
        if (c == Vec3(0.0)) continue;  // a dark light adds nothing: no shadow rays for it
        s.lights.push_back({Vec<T>(l.position - s.frameOrigin), boundedInput<T>(c), {}, {}});
    }
    const std::size_t count = scene.spheres.size();
    const bool useBvh = bvhChosen(static_cast<int>(count));
    BvhInput bvh;
    bvh.centres.resize(useBvh ? count : 0);
    bvh.radii.resize(useBvh ? count : 0);
    threads = resolveThreadCount(threads);
    prepareSpheres(scene, s, bvh, threads);
    if (sceneRead) sceneRead();  // nothing below reads `scene`
    if (useBvh) {
        s.bvh = sphereBvhFor<T>(bvh.centres, bvh.radii, s.spheres, bvhCache, s.frameOrigin,
                                s.camera.origin, threads);
        s.useBvh = true;
    } else {
        s.screenBoxes = sphereScreenBoxes(s.camera, s.spheres);
        for (PreparedLight<T>& light : s.lights)
            light.cones = shadowCones(light.position, s.spheres);
    }
    return s;
}

template <typename T>
void addLightBufferSlots(PreparedScene<T>& s) {
    if (!s.useBvh) return;
    for (PreparedLight<T>& light : s.lights)
        if (!light.buffer) light.buffer = std::make_shared<LightBufferSlot>();
}

template <typename T>
void addLightBuffers(PreparedScene<T>& s, int threads) {
    addLightBufferSlots(s);
    for (PreparedLight<T>& light : s.lights)
        if (light.buffer && light.buffer->claim())
            light.buffer->publish(lightBuffer(light.position, s.spheres, s.bvh->direct, threads));
}

template <typename T>
void considerLightBuffer(const PreparedScene<T>& s, const PreparedLight<T>& light,
                         const RayCounts& counts) {
    if (counts.shadow < kLightBufferProbe) return;
    LightBufferSlot& slot = *light.buffer;
    if (!slot.claim()) return;
    if (double(counts.shadowLoneLeaves) < kLoneLeavesPerShadowRay * double(counts.shadow)) return;
    slot.publish(lightBuffer(light.position, s.spheres, s.bvh->direct, 1));
}

// Every entry point runs in the kernel chosen at start (kernel_dispatch.h).
template <typename T>
std::optional<Hit<T>> closestHit(const PreparedScene<T>& s, const Ray<T>& ray, T tMax) {
    return activeKernel().entryPoints<T>().closestHit(s, ray, tMax);
}

template <typename T>
Vec<T> traceRay(const PreparedScene<T>& s, const Ray<T>& ray, int depth, RayCounts& counts) {
    return activeKernel().entryPoints<T>().traceRay(s, ray, depth, counts);
}

template <typename T>
void traceCameraSamples(const PreparedScene<T>& s, const CameraSample<T>* samples, int count,
                        Vec<T>* radiance, RayCounts& counts) {
    activeKernel().entryPoints<T>().traceCameraSamples(s, samples, count, radiance, counts);
}

template <typename T>
void traceCameraRows(const PreparedScene<T>& s, int y, int rows, int x0, int count, int n,
                     Vec<T>* radiance, RayCounts& counts) {
    activeKernel().entryPoints<T>().traceCameraRows(s, y, rows, x0, count, n, radiance, counts);
}

template <typename T>
void traceCameraRow(const PreparedScene<T>& s, int y, int x0, int count, int n, Vec<T>* radiance,
                    RayCounts& counts) {
    traceCameraRows(s, y, 1, x0, count, n, radiance, counts);
}

template <typename T>
void traceCameraBlock(const PreparedScene<T>& s, int y, int x0, int pixels, int n0, int samples,
                      Vec<T>* radiance, RayCounts& counts) {
    activeKernel().entryPoints<T>().traceCameraBlock(s, y, x0, pixels, n0, samples, radiance,
                                                     counts);
}

template <typename T>
void traceCameraRowAtDepths(const PreparedScene<T>& s, int y, int x0, int count, int n,
                            Vec<T>* radiance, const int* depths, int depthCount, Vec<T>* atDepths,
                            RayCounts& counts) {
    activeKernel().entryPoints<T>().traceCameraRowAtDepths(s, y, x0, count, n, radiance, depths,
                                                           depthCount, atDepths, counts);
}

template <typename T>
Vec<T> tracePixelSample(const PreparedScene<T>& s, int i, int j, T u, T v, RayCounts& counts) {
    const CameraSample<T> sample{i, j, u, v};
    Vec<T> radiance;
    traceCameraSamples(s, &sample, 1, &radiance, counts);
    return radiance;
}

template <typename T>
CameraSample<T> pixelSample(const PreparedScene<T>& s, int i, int j, int n) {
    if (s.samplesPerPixel == 1 || n == kPixelCentre) return {i, j, T(0.5), T(0.5)};
    const std::uint32_t seed = pixelSeed(i, j);
    const OffsetLanes<std::uint32_t> offset = sampleOffsets(n, s.openEndedSamples, s.pattern, seed);
    return {i, j, T(offset.u[0]), T(offset.v[0])};
}

#define WHITTED_INSTANTIATE(T)                                                                    \
    template PreparedScene<T> prepareScene<T>(const Scene&, BvhCache*, int,                       \
                                              const std::function<void()>&);                      \
    template void addLightBufferSlots<T>(PreparedScene<T>&);                                      \
    template void addLightBuffers<T>(PreparedScene<T>&, int);                                     \
    template void considerLightBuffer<T>(const PreparedScene<T>&, const PreparedLight<T>&,        \
                                         const RayCounts&);                                       \
    template std::optional<Hit<T>> closestHit<T>(const PreparedScene<T>&, const Ray<T>&, T);      \
    template Vec<T> traceRay<T>(const PreparedScene<T>&, const Ray<T>&, int, RayCounts&);         \
    template void traceCameraRows<T>(const PreparedScene<T>&, int, int, int, int, int, Vec<T>*,   \
                                     RayCounts&);                                                 \
    template void traceCameraRow<T>(const PreparedScene<T>&, int, int, int, int, Vec<T>*,         \
                                    RayCounts&);                                                  \
    template void traceCameraBlock<T>(const PreparedScene<T>&, int, int, int, int, int, Vec<T>*,  \
                                      RayCounts&);                                                \
    template void traceCameraRowAtDepths<T>(const PreparedScene<T>&, int, int, int, int, Vec<T>*, \
                                            const int*, int, Vec<T>*, RayCounts&);                \
    template void traceCameraSamples<T>(const PreparedScene<T>&, const CameraSample<T>*, int,     \
                                        Vec<T>*, RayCounts&);                                     \
    template Vec<T> tracePixelSample<T>(const PreparedScene<T>&, int, int, T, T, RayCounts&);     \
    template CameraSample<T> pixelSample<T>(const PreparedScene<T>&, int, int, int);
WHITTED_INSTANTIATE(float)
WHITTED_INSTANTIATE(double)
#undef WHITTED_INSTANTIATE

}  // namespace whitted
