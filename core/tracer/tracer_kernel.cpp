// The hot tracing code: packets, intersection and shading, the bodies behind
// tracer.h's entry points. core/CMakeLists.txt compiles this file once per
// instruction set with WHITTED_ISA naming it; all of it lives in that set's
// namespace (isa_namespace.h), and only kTracerKernel is visible outside.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "tracer/bvh_traverse.h"
#include "tracer/isa_namespace.h"
#include "tracer/lane_shading.h"
#include "tracer/ray_packet.h"
#include "tracer/sample_lanes.h"
#include "tracer/tracer_kernel.h"

// The per-ISA objects get WHITTED_ISA, _MARCH and _TUNE from CMake; built
// with the project's own flags (WHITTED_NATIVE), this is the "native" kernel.
#ifdef WHITTED_ISA_MARCH
#define WHITTED_KERNEL_NAME WHITTED_ISA_STR(WHITTED_ISA)
#else
#define WHITTED_KERNEL_NAME "native"
#define WHITTED_ISA_MARCH "native"
#define WHITTED_ISA_TUNE "native"
#endif

namespace whitted {
inline namespace WHITTED_ISA_NAMESPACE {

namespace {

template <typename T>
std::optional<Hit<T>> kernelClosestHit(const PreparedScene<T>& s, const Ray<T>& ray, T tMax) {
    RayPacket<T> packet;
    packet.set(0, ray.origin, ray.dir, ray.originSphere, ray.intoOrigin);
    packet.fromCamera = ray.fromCamera;
    typename Simd<T>::type t, k;
    sceneClosestHits(s.spheres, s.useBvh ? s.bvh.get() : nullptr, packet, t, k);
    if (k[0] < T(0) || !(t[0] < tMax)) return std::nullopt;
    return Hit<T>{t[0], static_cast<int>(k[0])};
}

template <typename T>
void tracePacket(const PreparedScene<T>& s, const RayPacket<T>& rays, int depth,
                 const typename Simd<T>::type& weight, Vec3x<T>& radiance, RayCounts& counts,
                 Vec3x<T>* levels);

// Where the lanes that hit are on their surfaces: the point, the normal
// facing the ray, and on which side the ray came from.
template <typename T>
struct SurfacePoint {
    using V = typename Simd<T>::type;
    Vec3x<T> d, p, outward, n;
    decltype(V{} > V{}) inside;  // the ray hit the surface from within
};

template <typename T>
SurfacePoint<T> surfacePoint(const RayPacket<T>& rays, const typename Simd<T>::type& tHit,
                             const LaneMaterials<T>& g) {
    SurfacePoint<T> sp;
    sp.d = rays.dirs();
    sp.p = rays.origins() + tHit * sp.d;
    // Normalised, not divided by the radius: p is off the surface by its
    // rounding error, and a normal that is not unit length makes reflect()
    // lengthen the ray, which puts the next hit further off; inside glass that
    // error grew sevenfold per internal reflection until float renders showed
    // speckles.
    sp.outward = normalize(sp.p - g.centre);
    sp.inside = dot(sp.d, sp.outward) > T(0);
    sp.n = select(sp.inside, -sp.outward, sp.outward);
    return sp;
}

// Each light's diffuse and specular share at the lanes that hit, dimmed by
// the transmittance of what lies between (one shadow packet per light).
template <typename T, typename Mask>
void addDirectLight(const PreparedScene<T>& s, const LaneMaterials<T>& g, const SurfacePoint<T>& sp,
                    const Mask& hit, const typename Simd<T>::type& kHit, const Vec3x<T>& kd,
                    Vec3x<T>& radiance, RayCounts& counts) {
    using V = typename Simd<T>::type;
    const Vec3x<T>& p = sp.p;
    const Vec3x<T>& n = sp.n;
    for (const PreparedLight<T>& light : s.lights) {
        Vec3x<T> l = Vec3x<T>::broadcast(light.position) - p;
        const V distance = laneSqrt(dot(l, l));
        l = l * (T(1) / distance);
        const V nl = dot(n, l);
        const auto lit = hit & g.lit & (distance > T(0)) & (nl > T(0));
        const unsigned litLanes = laneBits(lit);
        if (!litLanes) continue;
        counts.shadow += __builtin_popcount(litLanes);
        // The shadow ray goes into the sphere when it leaves p against the outward normal.
        const RayPacket<T> shadow =
            RayPacket<T>::of(p, l, kHit, dot(l, sp.outward) < T(0), litLanes);
        const LightBuffer* buffer = light.buffer ? light.buffer->ready() : nullptr;
        const V sj = sceneTransmittance(
            s.spheres, s.transparency, s.useBvh ? s.bvh.get() : nullptr, shadow, distance, litLanes,
            light.cones.empty() ? nullptr : light.cones.data(), buffer, &counts.shadowLoneLeaves);
        if (light.buffer && !buffer && !light.buffer->claimed())
            considerLightBuffer(s, light, counts);
        const auto shaded = lit & (sj != T(0));
        if (!laneBits(shaded)) continue;
        Vec3x<T> term = kd * nl;
        const auto glossy = shaded & (g.specular > T(0));
        if (laneBits(glossy)) {
            const V nh = dot(n, normalize(l - sp.d));
            const auto highlight = glossy & (nh > T(0));
            V spec = powLanes<T>(nh, highlight & (g.shininessInt >= 0) ? g.shininessInt : 0);
            for (unsigned bits = laneBits(highlight & (g.shininessInt < 0)); bits;
                 bits &= bits - 1) {
                const int i = __builtin_ctz(bits);
                spec[i] = std::pow(nh[i], g.shininess[i]);
            }
            const V add = g.specular * spec;
            term = select(highlight, term + Vec3x<T>{add, add, add}, term);
        }
        const Vec3x<T> colour = Vec3x<T>::broadcast(light.color);
        radiance = select(shaded, radiance + (sj * colour) * term, radiance);
    }
}

// A packet of secondary rays and the path's weight at each of its rays.
template <typename T>
struct Branch {
    RayPacket<T> rays;
    typename Simd<T>::type weight;
};

// Copies the rays of `from` into `to`'s lanes from `at` on, in lane order.
template <typename T>
void appendLanes(const Branch<T>& from, Branch<T>& to, int at) {
    for (unsigned bits = from.rays.active; bits; bits &= bits - 1, ++at) {
        const int l = __builtin_ctz(bits);
        to.rays.set(at, from.rays.origin(l), from.rays.dir(l), int(from.rays.originSphere[l]),
                    from.rays.intoOrigin[l] != 0);
        to.weight[at] = from.weight[l];
    }
}

// Gives lanes from `at` on of `merged` back to the lanes of `to`'s rays.
template <typename T>
void takeLanes(const Vec3x<T>& merged, const Branch<T>& to, int at, Vec3x<T>& radiance) {
    for (unsigned bits = to.rays.active; bits; bits &= bits - 1, ++at) {
        const int l = __builtin_ctz(bits);
        radiance.x[l] = merged.x[at];
        radiance.y[l] = merged.y[at];
        radiance.z[l] = merged.z[at];
    }
}

// The radiance along the refracted and the reflected rays of a packet's hits,
// each in its rays' own lanes. Deep in glass few lanes of a packet are left,
// and a packet costs the same vector operations however few lanes it holds:
// where both fit in one packet they are traced as one (a field of glass balls
// rendered 0.85 of the time at depth 13). A lane's result does not depend on
// the other lanes (bvh_traverse.h), so the picture is the same to the bit.
// Not where `levels` keeps each level's share: those sums, lane by lane of
// the camera packet, would be added up in another order.
template <typename T>
void traceBranches(const PreparedScene<T>& s, const Branch<T>& refracted,
                   const Branch<T>& reflected, int depth, Vec3x<T>& refractedRadiance,
                   Vec3x<T>& reflectedRadiance, RayCounts& counts, Vec3x<T>* levels) {
    const int nRefracted = __builtin_popcount(refracted.rays.active);
    const int nReflected = __builtin_popcount(reflected.rays.active);
    if (levels || !nRefracted || !nReflected || nRefracted + nReflected > RayPacket<T>::kWidth) {
        if (nRefracted)
            tracePacket(s, refracted.rays, depth, refracted.weight, refractedRadiance, counts,
                        levels);
        if (nReflected)
            tracePacket(s, reflected.rays, depth, reflected.weight, reflectedRadiance, counts,
                        levels);
        return;
    }
    Branch<T> both{refracted.rays, refracted.weight};
    both.rays.active = 0;
    appendLanes(refracted, both, 0);
    appendLanes(reflected, both, nRefracted);
    Vec3x<T> radiance;
    tracePacket(s, both.rays, depth, both.weight, radiance, counts, levels);
    refractedRadiance = reflectedRadiance = radiance;  // every lane set: no garbage to add up
    takeLanes(radiance, refracted, 0, refractedRadiance);
    takeLanes(radiance, reflected, nRefracted, reflectedRadiance);
}

// The refracted and reflected shares at the lanes that hit, each traced as a
// packet one level deeper (traceBranches()), each added in the order of the
// formula: refraction first, then reflection.
template <typename T, typename Mask>
void addSecondaryRays(const PreparedScene<T>& s, const LaneMaterials<T>& g,
                      const SurfacePoint<T>& sp, const Mask& hit,
                      const typename Simd<T>::type& kHit, int depth,
                      const typename Simd<T>::type& weight, Vec3x<T>& radiance, RayCounts& counts,
                      Vec3x<T>* levels) {
    using V = typename Simd<T>::type;
    // The lanes whose ray, passing on `share` of its weight, stays at or above
    // the scene's pruning weight (every lane when it is 0, as SPEC renders).
    auto heavyEnough = [&](const V& share) {
        return s.pruneBelow > T(0) ? laneBits(weight * share >= s.pruneBelow) : ~0u;
    };
    const Vec3x<T>& d = sp.d;
    const Vec3x<T>& n = sp.n;
    V reflectWeight = g.reflectivity;
    // No rays until the refracted ones are made below.
    Branch<T> refracted{RayPacket<T>::of(sp.p, d, kHit, ~sp.inside, 0), weight * g.transparency};
    auto passes = hit & (g.transparency > T(0));
    if (laneBits(passes)) {
        const V eta = sp.inside ? g.ior : T(1) / g.ior;
        const V cosi = -dot(d, n);
        const V k = T(1) - eta * eta * (T(1) - cosi * cosi);
        // Total internal reflection: the refracted share follows the reflected
        // ray, which is traced once for both shares.
        reflectWeight = passes & ~(k >= T(0)) ? reflectWeight + g.transparency : reflectWeight;
        passes = passes & (k >= T(0));
        if (const unsigned bits = laneBits(passes) & heavyEnough(g.transparency)) {
            const V root = laneSqrt(passes ? k : V{});
            const Vec3x<T> t = normalize(eta * d + (eta * cosi - root) * n);
            // Refracted rays cross the surface: into the sphere from outside, out from inside.
            refracted.rays = RayPacket<T>::of(sp.p, t, kHit, ~sp.inside, bits);
            counts.refraction += __builtin_popcount(bits);
        }
    }
    const auto mirror = hit & (reflectWeight > T(0));
    const unsigned reflectedBits = laneBits(mirror) & heavyEnough(reflectWeight);
    if (!refracted.rays.active && !reflectedBits) return;  // matte hits: nothing deeper
    const Vec3x<T> r = d - (T(2) * dot(d, n)) * n;         // reflect(d, n)
    const Branch<T> reflected{RayPacket<T>::of(sp.p, r, kHit, sp.inside, reflectedBits),
                              weight * reflectWeight};
    counts.reflection += __builtin_popcount(reflectedBits);
    Vec3x<T> refractedRadiance, reflectedRadiance;
    traceBranches(s, refracted, reflected, depth + 1, refractedRadiance, reflectedRadiance, counts,
                  levels);
    if (refracted.rays.active) {
        const auto traced = passes & maskFromBits<T>(refracted.rays.active);
        radiance = select(traced, radiance + g.transparency * refractedRadiance, radiance);
    }
    if (reflectedBits) {
        const auto traced = mirror & maskFromBits<T>(reflectedBits);
        radiance = select(traced, radiance + reflectWeight * reflectedRadiance, radiance);
    }
}

// What the rays of a packet add at their own level, before their reflected
// and refracted rays: `local` at the path's weight, into levels[depth] for
// the lanes traced (none when levels is null, as in every render).
template <typename T>
void addToLevel(Vec3x<T>* levels, int depth, const RayPacket<T>& rays,
                const typename Simd<T>::type& weight, const Vec3x<T>& local) {
    if (!levels) return;
    Vec3x<T>& level = levels[depth];
    level = select(maskFromBits<T>(rays.active), level + weight * local, level);
}

// Radiance along every ray of a packet at the given depth: the Whitted sum of
// SPEC §3, computed for all lanes at once, with the shadow, reflected and
// refracted rays of all lanes traced as packets. `levels`, if not null, gets
// each level's share of it (addToLevel()).
template <typename T>
void tracePacket(const PreparedScene<T>& s, const RayPacket<T>& rays, int depth,
                 const typename Simd<T>::type& weight, Vec3x<T>& radiance, RayCounts& counts,
                 Vec3x<T>* levels) {
    using V = typename Simd<T>::type;
    V tHit, kHit;
    sceneClosestHits(s.spheres, s.useBvh ? s.bvh.get() : nullptr, rays, tHit, kHit);
    radiance = Vec3x<T>::broadcast(s.background);
    const auto hit = (kHit >= T(0)) & maskFromBits<T>(rays.active);
    const unsigned lanes = laneBits(hit);
    if (!lanes) {
        addToLevel(levels, depth, rays, weight, radiance);
        return;
    }

    const LaneMaterials<T> g = gatherMaterials(s, kHit, lanes);
    const SurfacePoint<T> sp = surfacePoint(rays, tHit, g);
    Vec3x<T> kd = g.diffuse;
    if (laneBits(g.checker & hit)) kd = select(g.checker, checkerLanes(g, sp.p, sp.outward), kd);
    radiance = select(hit, Vec3x<T>::broadcast(s.ambient) * kd, radiance);
    addDirectLight(s, g, sp, hit, kHit, kd, radiance, counts);
    addToLevel(levels, depth, rays, weight, radiance);
    if (depth < s.maxDepth)
        addSecondaryRays(s, g, sp, hit, kHit, depth, weight, radiance, counts, levels);
}

template <typename T>
Vec<T> kernelTraceRay(const PreparedScene<T>& s, const Ray<T>& ray, int depth, RayCounts& counts) {
    RayPacket<T> packet;
    packet.set(0, ray.origin, ray.dir, ray.originSphere, ray.intoOrigin);
    packet.fromCamera = ray.fromCamera;
    Vec3x<T> radiance;
    tracePacket(s, packet, depth, typename Simd<T>::type{} + T(1), radiance, counts,
                static_cast<Vec3x<T>*>(nullptr));
    return radiance.lane(0);
}

// The spheres that camera rays through (x, y), in the first m lanes, can meet
// (screen_boxes.h): with no tree, a packet in the sky tests none.
template <typename T>
std::uint32_t spheresInView(const PreparedScene<T>& s, const typename Simd<T>::type& x,
                            const typename Simd<T>::type& y, int m) {
    if (s.screenBoxes.empty()) return ~0u;
    float xMin = float(x[0]), xMax = xMin, yMin = float(y[0]), yMax = yMin;
    for (int l = 1; l < m; ++l) {
        xMin = std::min(xMin, float(x[l]));
        xMax = std::max(xMax, float(x[l]));
        yMin = std::min(yMin, float(y[l]));
        yMax = std::max(yMax, float(y[l]));
    }
    return spheresInView(s.screenBoxes, xMin, xMax, yMin, yMax);
}

// Camera rays through image-plane positions (x, y) = (i + u, j + v) for the
// first m lanes: cameraDirection() for every lane at once, operation for operation.
template <typename T>
void traceCameraPacket(const PreparedScene<T>& s, typename Simd<T>::type x,
                       typename Simd<T>::type y, int m, Vec3x<T>& radiance, RayCounts& counts,
                       Vec3x<T>* levels = nullptr) {
    using V = typename Simd<T>::type;
    const CameraBasis<T>& cam = s.camera;
    const std::uint32_t spheres = spheresInView(s, x, y, m);
    x = (x / T(cam.width) * T(2) - T(1)) * cam.tanHalfFov * cam.aspect;
    y = (T(1) - y / T(cam.height) * T(2)) * cam.tanHalfFov;
    const Vec3x<T> dir =
        normalize(Vec3x<T>::broadcast(cam.forward) + x * Vec3x<T>::broadcast(cam.right) +
                  y * Vec3x<T>::broadcast(cam.up));
    RayPacket<T> packet = RayPacket<T>::of(Vec3x<T>::broadcast(cam.origin), dir, V{} - T(1),
                                           typename RayPacket<T>::Mask{}, (1u << m) - 1, true);
    packet.spheres = spheres;
    counts.camera += m;
    tracePacket(s, packet, 0, V{} + T(1), radiance, counts, levels);
}

// Camera rays for `count` samples in packets; place(first, m, x, y) puts the
// image-plane positions (i + u, j + v) of samples first .. first+m-1 in lanes.
template <typename T, typename Place>
void traceCameraPackets(const PreparedScene<T>& s, int count, Vec<T>* radiance, RayCounts& counts,
                        Place place) {
    constexpr int W = RayPacket<T>::kWidth;
    using V = typename Simd<T>::type;
    for (int first = 0; first < count; first += W) {
        const int m = std::min(W, count - first);
        V x{}, y{};
        place(first, m, x, y);
        Vec3x<T> out;
        traceCameraPacket(s, x, y, m, out, counts);
        for (int l = 0; l < m; ++l) radiance[first + l] = out.lane(l);
    }
}

template <typename T>
void kernelCameraSamples(const PreparedScene<T>& s, const CameraSample<T>* samples, int count,
                         Vec<T>* radiance, RayCounts& counts) {
    using V = typename Simd<T>::type;
    traceCameraPackets(s, count, radiance, counts, [&](int first, int m, V& x, V& y) {
        for (int l = 0; l < m; ++l) {
            const CameraSample<T>& cs = samples[first + l];
            x[l] = T(cs.i) + cs.u;
            y[l] = T(cs.j) + cs.v;
        }
    });
}

// Where samples n0 .. n0+samples-1 of the pixels x0, x0+1, ... of row y lie,
// as pixelSample() gives them, pixel by pixel: place(first, m, px, py) fills
// lanes first .. first+m-1, lane q with sample n0 + q % samples of pixel
// x0 + q / samples.
template <typename T>
auto blockPlacer(const PreparedScene<T>& s, int y, int x0, int n0, int samples) {
    using V = typename Simd<T>::type;
    using U = typename LaneWords<T>::type;
    return [&s, y, x0, n0, samples](int first, int m, V& px, V& py) {
        U column{}, index{};
        int pixel = first / samples, sample = first % samples;
        for (int l = 0; l < m; ++l) {
            column[l] = std::uint32_t(x0 + pixel);
            index[l] = std::uint32_t(n0 + sample);
            if (++sample == samples) sample = 0, ++pixel;
        }
        const OffsetLanes<U> offset = sampleOffsets(index, s.openEndedSamples, s.pattern,
                                                    pixelSeeds(column, std::uint32_t(y)));
        for (int l = 0; l < m; ++l) {
            px[l] = T(column[l]) + T(offset.u[l]);
            py[l] = T(y) + T(offset.v[l]);
        }
    };
}

// The rows of pixels a camera packet spans: about as many as its columns.
template <typename T>
constexpr int kPacketRows = RayPacket<T>::kWidth >= 16  ? 4
                            : RayPacket<T>::kWidth >= 4 ? 2
                                                        : 1;

// The lanes of a packet of `across` x `tall` pixels: lane l at column
// l % across and row l / across of the block, as words and as values.
template <typename T>
struct BlockLanes {
    typename LaneWords<T>::type column{}, row{};
    typename Simd<T>::type x{}, y{};
    int across = 0, tall = 0;

    BlockLanes(int acrossPixels, int tallPixels) : across(acrossPixels), tall(tallPixels) {
        for (int l = 0; l < across * tall; ++l) {
            column[l] = std::uint32_t(l % across);
            row[l] = std::uint32_t(l / across);
            x[l] = T(column[l]);
            y[l] = T(row[l]);
        }
    }
};

// Where sample n of each pixel of a block from (x, y) lies (BlockLanes), as
// pixelSample() gives it: the centre at one sample a pixel.
template <typename T>
void blockSamplePositions(const PreparedScene<T>& s, const BlockLanes<T>& b, int x, int y, int n,
                          typename Simd<T>::type& px, typename Simd<T>::type& py) {
    if (s.samplesPerPixel == 1 || n == kPixelCentre) {
        px = (b.x + T(x)) + T(0.5);  // exact integers, then the centre: as pixelSample()
        py = (b.y + T(y)) + T(0.5);
    } else {
        const auto column = b.column + std::uint32_t(x), row = b.row + std::uint32_t(y);
        const auto offset =
            sampleOffsets(n, s.openEndedSamples, s.pattern, pixelSeeds(column, row));
        for (int l = 0; l < b.across * b.tall; ++l) {
            px[l] = T(column[l]) + T(offset.u[l]);
            py[l] = T(row[l]) + T(offset.v[l]);
        }
    }
}

// One packet, a block of pixels from (x, y) (BlockLanes), sample n of each
// (blockSamplePositions()), its radiance stored row by row into `radiance`
// (`stride` a row).
template <typename T>
void traceBlockOfPixels(const PreparedScene<T>& s, const BlockLanes<T>& b, int x, int y, int n,
                        Vec<T>* radiance, int stride, RayCounts& counts) {
    typename Simd<T>::type px{}, py{};
    blockSamplePositions(s, b, x, y, n, px, py);
    Vec3x<T> out;
    traceCameraPacket(s, px, py, b.across * b.tall, out, counts);
    for (int r = 0, l = 0; r < b.tall; ++r, radiance += stride)
        for (int c = 0; c < b.across; ++c, ++l) radiance[c] = out.lane(l);
}

template <typename T>
void kernelCameraRows(const PreparedScene<T>& s, int y, int rows, int x0, int count, int n,
                      Vec<T>* radiance, RayCounts& counts) {
    constexpr int W = RayPacket<T>::kWidth;
    // Made once: filled lane by lane for every four rows, the lanes took
    // about 4 % of a seed render (perf's samples).
    static const BlockLanes<T> square(W / kPacketRows<T>, kPacketRows<T>);
    for (int r = 0; r < rows; r += kPacketRows<T>) {
        const int tall = std::min(kPacketRows<T>, rows - r);
        const int wide = W / tall;
        const BlockLanes<T> whole = tall == kPacketRows<T> ? square : BlockLanes<T>(wide, tall);
        Vec<T>* out = radiance + std::size_t(r) * count;
        int c = 0;
        for (; c + wide <= count; c += wide)
            traceBlockOfPixels(s, whole, x0 + c, y + r, n, out + c, count, counts);
        if (c < count)
            traceBlockOfPixels(s, BlockLanes<T>(count - c, tall), x0 + c, y + r, n, out + c, count,
                               counts);
    }
}

// Samples n0 .. n0+samples-1 of the pixels x0, x0+1, ... of row y, pixel by
// pixel (blockPlacer()).
template <typename T>
void kernelCameraBlock(const PreparedScene<T>& s, int y, int x0, int pixels, int n0, int samples,
                       Vec<T>* radiance, RayCounts& counts) {
    traceCameraPackets(s, pixels * samples, radiance, counts, blockPlacer(s, y, x0, n0, samples));
}

// Sample n of the pixels x0 .. x0+count-1 of row y, a packet a run of pixels
// along the row, each packet's levels kept and summed up to each of the
// shallower depths (ascending, none past the scene's max depth).
template <typename T>
void kernelCameraRowAtDepths(const PreparedScene<T>& s, int y, int x0, int count, int n,
                             Vec<T>* radiance, const int* depths, int depthCount, Vec<T>* atDepths,
                             RayCounts& counts) {
    constexpr int W = RayPacket<T>::kWidth;
    using V = typename Simd<T>::type;
    const BlockLanes<T> run(W, 1);
    std::array<Vec3x<T>, kMaxDepth + 1> levels;
    for (int first = 0; first < count; first += W) {
        const int m = std::min(W, count - first);
        V px{}, py{};
        blockSamplePositions(s, m == W ? run : BlockLanes<T>(m, 1), x0 + first, y, n, px, py);
        std::fill_n(levels.begin(), s.maxDepth + 1, Vec3x<T>::broadcast(Vec<T>(T(0))));
        Vec3x<T> out;
        traceCameraPacket(s, px, py, m, out, counts, levels.data());
        for (int l = 0; l < m; ++l) {
            radiance[first + l] = out.lane(l);
            Vec<T> sum(T(0));
            int level = 0;
            for (int j = 0; j < depthCount; ++j) {
                for (; level <= depths[j]; ++level) sum += levels[level].lane(l);
                atDepths[std::size_t(first + l) * depthCount + j] = sum;
            }
        }
    }
}

}  // namespace

// Constant-initialised, so loading an object built for a newer CPU runs none of
// its instructions until the dispatcher has chosen it.
extern const TracerKernel kTracerKernel;
constinit const TracerKernel kTracerKernel{
    .name = WHITTED_KERNEL_NAME,
    .isa = WHITTED_ISA_MARCH,
    .tune = WHITTED_ISA_TUNE,
    .vectorBytes = kSimdBytes,
    .floats = {kernelClosestHit<float>, kernelTraceRay<float>, kernelCameraSamples<float>,
               kernelCameraRows<float>, kernelCameraRowAtDepths<float>, kernelCameraBlock<float>},
    .doubles = {kernelClosestHit<double>, kernelTraceRay<double>, kernelCameraSamples<double>,
                kernelCameraRows<double>, kernelCameraRowAtDepths<double>,
                kernelCameraBlock<double>},
};

}  // namespace WHITTED_ISA_NAMESPACE
}  // namespace whitted
