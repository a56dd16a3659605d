// SIMD vectors of float or double through GCC's vector extensions, and the few
// lane operations they lack (masks as bits, square root, floor).
//
// The tracer's hot paths run 16 floats or 8 doubles at once with AVX-512, 8 or 4
// with AVX, and pairs of SSE instructions elsewhere. Each lane performs IEEE
// operations of its own, so a lane's result never depends on its neighbours.
#pragma once

#include <cmath>
#if defined(__AVX__)
#include <immintrin.h>
#endif

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

}  // namespace whitted
