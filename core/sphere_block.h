// Spheres in blocks of SIMD width, intersected several at once.
//
// The hit loop is the tracer's hot path: most rays test every sphere, and one
// scalar test costs about 70 instructions. Here a block of 8 floats (4 doubles)
// is tested with GCC vector extensions, which compile to AVX where the CPU has
// it and to pairs of SSE instructions where it does not. Every lane performs
// exactly the operations of intersectSphere() in sphere_intersect.h, in the same
// order, so both give bit-identical roots (tests/core/test_sphere_block.cpp).
#pragma once

#include <cmath>
#if defined(__AVX__)
#include <immintrin.h>
#endif
#include <cstring>
#include <limits>
#include <optional>
#include <vector>

#include "sphere_intersect.h"

namespace whitted {

// The widest vectors the target has: 64 bytes with AVX-512, else 32 (AVX, or
// pairs of SSE instructions). The attribute cannot take a template parameter,
// hence the two specialisations.
#if defined(__AVX512F__)
inline constexpr int kSimdBytes = 64;
#else
inline constexpr int kSimdBytes = 32;
#endif
template <typename T>
struct Simd;
template <>
struct Simd<float> {
    typedef float type __attribute__((vector_size(kSimdBytes)));
};
template <>
struct Simd<double> {
    typedef double type __attribute__((vector_size(kSimdBytes)));
};

template <typename T>
struct SphereBlock {
    static constexpr int kWidth = kSimdBytes / sizeof(T);
    using V = typename Simd<T>::type;
    V cx, cy, cz;  // centre
    V rrHi, rrLo;  // radius^2 == rrHi + rrLo exactly; padding lanes have rrHi = -1 (never hit)
    V cameraC;     // accurateOffsetSquared() from the camera position
};

// All spheres of a scene in blocks; sphere k is lane k % kWidth of block k / kWidth.
template <typename T>
struct SphereBlocks {
    std::vector<SphereBlock<T>> blocks;
    int count = 0;

    void assign(const std::vector<Vec<T>>& centre, const std::vector<T>& rrHi,
                const std::vector<T>& rrLo, const std::vector<T>& cameraC) {
        constexpr int W = SphereBlock<T>::kWidth;
        count = static_cast<int>(centre.size());
        blocks.assign((centre.size() + W - 1) / W, SphereBlock<T>{});
        // Padding lanes must miss on both paths: a negative r^2 makes the
        // discriminant negative, a huge camera c keeps them off the near path.
        for (auto& b : blocks)
            for (int l = 0; l < W; ++l) {
                b.rrHi[l] = T(-1);
                b.cameraC[l] = std::numeric_limits<T>::max();
            }
        for (int k = 0; k < count; ++k) {
            SphereBlock<T>& b = blocks[k / W];
            const int l = k % W;
            b.cx[l] = centre[k].x;
            b.cy[l] = centre[k].y;
            b.cz[l] = centre[k].z;
            b.rrHi[l] = rrHi[k];
            b.rrLo[l] = rrLo[k];
            b.cameraC[l] = cameraC[k];
        }
    }
};

// Lane masks as bits, lane l at bit l, and an element-wise square root. AVX
// has single instructions for both; the fallback loops give the same results.
template <typename M>
inline unsigned laneBits(const M& m) {
#if defined(__AVX512F__)
    const __m512i v = reinterpret_cast<__m512i>(m);
    if constexpr (sizeof(m[0]) == 4)
        return static_cast<unsigned>(_mm512_test_epi32_mask(v, v));
    else
        return static_cast<unsigned>(_mm512_test_epi64_mask(v, v));
#elif defined(__AVX__)
    if constexpr (sizeof(m[0]) == 4)
        return static_cast<unsigned>(_mm256_movemask_ps(reinterpret_cast<__m256>(m)));
    else
        return static_cast<unsigned>(_mm256_movemask_pd(reinterpret_cast<__m256d>(m)));
#else
    unsigned bits = 0;
    for (unsigned l = 0; l < sizeof(M) / sizeof(m[0]); ++l) bits |= (m[l] ? 1u : 0u) << l;
    return bits;
#endif
}

template <typename V>
inline V laneSqrt(const V& v) {
#if defined(__AVX512F__)
    if constexpr (sizeof(v[0]) == 4)
        return reinterpret_cast<V>(_mm512_maskz_sqrt_ps(0xFFFF, reinterpret_cast<__m512>(v)));
    else
        return reinterpret_cast<V>(_mm512_maskz_sqrt_pd(0xFF, reinterpret_cast<__m512d>(v)));
#elif defined(__AVX__)
    if constexpr (sizeof(v[0]) == 4)
        return reinterpret_cast<V>(_mm256_sqrt_ps(reinterpret_cast<__m256>(v)));
    else
        return reinterpret_cast<V>(_mm256_sqrt_pd(reinterpret_cast<__m256d>(v)));
#else
    V r;
    for (unsigned l = 0; l < sizeof(V) / sizeof(v[0]); ++l) r[l] = std::sqrt(v[l]);
    return r;
#endif
}

template <typename V>
inline V laneFloor(const V& v) {
#if defined(__AVX512F__)
    if constexpr (sizeof(v[0]) == 4)
        return reinterpret_cast<V>(
            _mm512_maskz_roundscale_ps(0xFFFF, reinterpret_cast<__m512>(v), 0x09));
    else
        return reinterpret_cast<V>(
            _mm512_maskz_roundscale_pd(0xFF, reinterpret_cast<__m512d>(v), 0x09));
#elif defined(__AVX__)
    if constexpr (sizeof(v[0]) == 4)
        return reinterpret_cast<V>(_mm256_floor_ps(reinterpret_cast<__m256>(v)));
    else
        return reinterpret_cast<V>(_mm256_floor_pd(reinterpret_cast<__m256d>(v)));
#else
    V r;
    for (unsigned l = 0; l < sizeof(V) / sizeof(v[0]); ++l) r[l] = std::floor(v[l]);
    return r;
#endif
}

// Roots of one ray against one block, for the lanes set in `lanes` (others are
// reported as misses and cost no exact-arithmetic fix-up). Either root of a
// valid lane may be behind the origin.
template <typename T>
struct BlockRoots {
    using V = typename SphereBlock<T>::V;
    V tNear, tFar;
    unsigned valid;  // bit l: lane l is hit by the ray's line
};

template <typename T>
inline BlockRoots<T> intersectBlock(const SphereBlock<T>& s, const Vec<T>& o, const Vec<T>& d,
                                    bool useCameraC, unsigned lanes) {
    using V = typename SphereBlock<T>::V;
    const V fx = o.x - s.cx, fy = o.y - s.cy, fz = o.z - s.cz;
    const V b = fx * d.x + fy * d.y + fz * d.z;
    const V ff = fx * fx + fy * fy + fz * fz;
    V c = useCameraC ? s.cameraC : ff - s.rrHi;
    const auto away = (b > T(0)) & (c > ff * (T(16) * std::numeric_limits<T>::epsilon()));
    const auto nearSurface = (c < ff * T(0.0625)) & (c > -(ff * T(0.0625)));
    if (!useCameraC) {
        unsigned fix = laneBits(nearSurface & ~away) & lanes;
        for (; fix; fix &= fix - 1) {
            const int l = __builtin_ctz(fix);
            c[l] =
                accurateOffsetSquared(o, Vec<T>(s.cx[l], s.cy[l], s.cz[l]), s.rrHi[l], s.rrLo[l]);
        }
    }
    const V px = fx - b * d.x, py = fy - b * d.y, pz = fz - b * d.z;
    const V discNear = b * b - c;
    const V discFar = s.rrHi - (px * px + py * py + pz * pz);
    const V disc = nearSurface ? discNear : discFar;
    const auto hit = ~away & (disc >= T(0));
    BlockRoots<T> r;
    r.valid = laneBits(hit) & lanes;
    if (!r.valid) return r;
    const V root = laneSqrt(hit ? disc : V{});
    const V q = -b - (b < T(0) ? -root : root);  // as in intersectSphere()
    const auto zero = q == T(0);
    const V t0 = zero ? V{} : c / (zero ? V{} + T(1) : q);
    const V t1 = zero ? V{} : q;
    const auto ordered = t0 < t1;
    r.tNear = ordered ? t0 : t1;
    r.tFar = ordered ? t1 : t0;
    return r;
}

}  // namespace whitted
