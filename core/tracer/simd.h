// SIMD vectors of float or double through GCC's vector extensions, and the few
// lane operations they lack (masks as bits, square root, floor).
//
// The tracer's hot paths run 16 floats or 8 doubles at once with AVX-512, 8 or 4
// with AVX, and 4 or 2 with SSE alone. Each lane performs IEEE
// operations of its own, so a lane's result never depends on its neighbours.
#pragma once

#include <cmath>
#include "tracer/isa_namespace.h"
#if defined(__SSE2__)
#include <immintrin.h>
#endif
#include <type_traits>

namespace whitted {

inline namespace WHITTED_ISA_NAMESPACE {

// The widest vectors the target has: 64 bytes with AVX-512, 32 with AVX, 16
// with SSE alone (wider ones would be split into SSE halves, passed through
// memory between functions). Lanes are independent, so the width changes
// speed, never results. The attribute cannot take a template parameter, hence
// the two specialisations.
#if defined(__AVX512F__)
inline constexpr int kSimdBytes = 64;
#elif defined(__AVX__)
inline constexpr int kSimdBytes = 32;
#else
inline constexpr int kSimdBytes = 16;
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
// laneBits() also takes a mask half as wide as the target's vectors (the float
// box tests of double packets, bvh_slabs.h).
template <typename M>
inline unsigned laneBits(const M& m) {
    constexpr bool kFloat = sizeof(m[0]) == 4;
#if defined(__AVX512F__)
    if constexpr (sizeof(M) == 64) {
        const __m512i v = reinterpret_cast<__m512i>(m);
        if constexpr (kFloat)
            return static_cast<unsigned>(_mm512_test_epi32_mask(v, v));
        else
            return static_cast<unsigned>(_mm512_test_epi64_mask(v, v));
    }
#endif
#if defined(__AVX__)
    if constexpr (sizeof(M) == 32) {
        if constexpr (kFloat)
            return static_cast<unsigned>(_mm256_movemask_ps(reinterpret_cast<__m256>(m)));
        else
            return static_cast<unsigned>(_mm256_movemask_pd(reinterpret_cast<__m256d>(m)));
    }
#endif
#if defined(__SSE2__)
    if constexpr (sizeof(M) == 16) {
        if constexpr (kFloat)
            return static_cast<unsigned>(_mm_movemask_ps(reinterpret_cast<__m128>(m)));
        else
            return static_cast<unsigned>(_mm_movemask_pd(reinterpret_cast<__m128d>(m)));
    }
#endif
    unsigned bits = 0;
    for (unsigned l = 0; l < sizeof(M) / sizeof(m[0]); ++l) bits |= (m[l] ? 1u : 0u) << l;
    return bits;
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
#elif defined(__SSE2__)
    if constexpr (sizeof(v[0]) == 4)
        return reinterpret_cast<V>(_mm_sqrt_ps(reinterpret_cast<__m128>(v)));
    else
        return reinterpret_cast<V>(_mm_sqrt_pd(reinterpret_cast<__m128d>(v)));
#else
    V r{};
    for (unsigned l = 0; l < sizeof(V) / sizeof(v[0]); ++l) r[l] = std::sqrt(v[l]);
    return r;
#endif
}

#if defined(__FMA__)
// a * b + c rounded once, per lane: what std::fma gives one lane. Only where
// the target has FMA, as exact::twoProduct() uses std::fma only there.
template <typename V>
inline V laneFma(const V& a, const V& b, const V& c) {
#if defined(__AVX512F__)
    if constexpr (sizeof(V) == 64) {
        if constexpr (sizeof(a[0]) == 4)
            return reinterpret_cast<V>(_mm512_fmadd_ps(reinterpret_cast<__m512>(a),
                                                       reinterpret_cast<__m512>(b),
                                                       reinterpret_cast<__m512>(c)));
        else
            return reinterpret_cast<V>(_mm512_fmadd_pd(reinterpret_cast<__m512d>(a),
                                                       reinterpret_cast<__m512d>(b),
                                                       reinterpret_cast<__m512d>(c)));
    }
#endif
    if constexpr (sizeof(V) == 32) {
        if constexpr (sizeof(a[0]) == 4)
            return reinterpret_cast<V>(_mm256_fmadd_ps(reinterpret_cast<__m256>(a),
                                                       reinterpret_cast<__m256>(b),
                                                       reinterpret_cast<__m256>(c)));
        else
            return reinterpret_cast<V>(_mm256_fmadd_pd(reinterpret_cast<__m256d>(a),
                                                       reinterpret_cast<__m256d>(b),
                                                       reinterpret_cast<__m256d>(c)));
    } else {
        V r{};
        for (unsigned l = 0; l < sizeof(V) / sizeof(a[0]); ++l) r[l] = std::fma(a[l], b[l], c[l]);
        return r;
    }
}
#endif

// floor() with SSE2 alone, which has no rounding instruction: adding and
// subtracting 2^23 (2^52 for double) rounds |v| to a whole number, exactly,
// then one step down fixes what rounded up. Larger magnitudes and NaN are
// their own floor, and so is a zero, whose sign the snapping would lose.
template <typename V>
inline V floorBySnapping(const V& v) {
    using T = std::remove_cvref_t<decltype(v[0])>;
    constexpr T kWhole = sizeof(T) == 4 ? T(8388608.0) : T(4503599627370496.0);
    const V magnitude = v < T(0) ? -v : v;
    V r = (magnitude + kWhole) - kWhole;
    r = v < T(0) ? -r : r;
    r = r > v ? r - T(1) : r;
    return ((magnitude < kWhole) & (r != v)) ? r : v;
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
#elif defined(__SSE4_1__)
    if constexpr (sizeof(v[0]) == 4)
        return reinterpret_cast<V>(_mm_floor_ps(reinterpret_cast<__m128>(v)));
    else
        return reinterpret_cast<V>(_mm_floor_pd(reinterpret_cast<__m128d>(v)));
#elif defined(__SSE2__)
    return floorBySnapping(v);
#else
    V r{};
    for (unsigned l = 0; l < sizeof(V) / sizeof(v[0]); ++l) r[l] = std::floor(v[l]);
    return r;
#endif
}

}  // namespace WHITTED_ISA_NAMESPACE
}  // namespace whitted
