// 3-vectors for a whole packet of rays: one SIMD vector per component, so that
// shading runs on every lane at once. Each operation is the one glm performs
// for a single Vec<T>, lane by lane, so a lane's result does not depend on
// which other rays share its packet.
#pragma once

#include <glm/vec3.hpp>

#include "tracer/isa_namespace.h"
#include "tracer/simd.h"

namespace whitted {

template <typename T>
using Vec = glm::vec<3, T, glm::defaultp>;

inline namespace WHITTED_ISA_NAMESPACE {

template <typename T>
struct Vec3x {
    using V = typename Simd<T>::type;
    // Not zeroed: every Vec3x the kernel declares is written whole before it
    // is read, and zeroing the large structs made of them (LaneMaterials) was
    // a memset call per packet.
    V x, y, z;

    static Vec3x broadcast(const Vec<T>& v) { return {V{} + v.x, V{} + v.y, V{} + v.z}; }
    Vec<T> lane(int l) const { return {x[l], y[l], z[l]}; }
    void setLane(int l, const Vec<T>& v) {
        x[l] = v.x;
        y[l] = v.y;
        z[l] = v.z;
    }
};

template <typename T>
inline Vec3x<T> operator+(const Vec3x<T>& a, const Vec3x<T>& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <typename T>
inline Vec3x<T> operator-(const Vec3x<T>& a, const Vec3x<T>& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <typename T>
inline Vec3x<T> operator-(const Vec3x<T>& a) {
    return {-a.x, -a.y, -a.z};
}
template <typename T>
inline Vec3x<T> operator*(const Vec3x<T>& a, const Vec3x<T>& b) {
    return {a.x * b.x, a.y * b.y, a.z * b.z};
}
template <typename T>
inline Vec3x<T> operator*(const typename Simd<T>::type& s, const Vec3x<T>& a) {
    return {s * a.x, s * a.y, s * a.z};
}
template <typename T>
inline Vec3x<T> operator*(const Vec3x<T>& a, const typename Simd<T>::type& s) {
    return {a.x * s, a.y * s, a.z * s};
}
template <typename T>
inline typename Simd<T>::type dot(const Vec3x<T>& a, const Vec3x<T>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
// glm::normalize: v * (1 / sqrt(dot(v, v))).
template <typename T>
inline Vec3x<T> normalize(const Vec3x<T>& v) {
    const typename Simd<T>::type inverseLength = T(1) / laneSqrt(dot(v, v));
    return v * inverseLength;
}
template <typename T, typename M>
inline Vec3x<T> select(const M& mask, const Vec3x<T>& a, const Vec3x<T>& b) {
    return {mask ? a.x : b.x, mask ? a.y : b.y, mask ? a.z : b.z};
}

}  // namespace WHITTED_ISA_NAMESPACE
}  // namespace whitted
