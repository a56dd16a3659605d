#include "image/srgb.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>

namespace whitted {

float srgbEncode(float linear) {
    if (!(linear > 0.0f)) return 0.0f;
    if (linear >= 1.0f) return 1.0f;
    if (linear <= 0.0031308f) return 12.92f * linear;
    return 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

namespace {

std::uint8_t encodeByFormula(float linear) {
    return static_cast<std::uint8_t>(std::lround(srgbEncode(linear) * 255.0f));
}

// thresholds[k]: the smallest float whose code is above k. Found by bisection
// on the formula itself, so the tables give exactly the formula's codes; the
// editor converts every frame with them, and std::pow per channel would cost
// 30 ms for a 1280x720 frame.
std::array<float, 255> makeThresholds() {
    std::array<float, 255> t{};
    for (int k = 0; k < 255; ++k) {
        // Non-negative floats order like their bit patterns.
        std::uint32_t lo = 0, hi = 0x3f800000;  // 0.0f, 1.0f: code(1) = 255 > k
        while (lo < hi) {
            const std::uint32_t mid = lo + (hi - lo) / 2;
            float x;
            std::memcpy(&x, &mid, sizeof x);
            if (encodeByFormula(x) > k)
                hi = mid;
            else
                lo = mid + 1;
        }
        std::memcpy(&t[k], &lo, sizeof(float));
    }
    return t;
}

const std::array<float, 255> kThresholds = makeThresholds();

// Buckets of 2^16 bit patterns (the top 7 bits of the mantissa): a bucket
// spans at most 0.8 % of its values, less than the 0.9 % between two codes'
// thresholds near 1.0, the closest they come, so it holds at most one
// threshold. Each bucket keeps the code of its smallest float and the
// threshold of the next code: one comparison then gives the exact code.
constexpr int kBucketShift = 16;
constexpr int kBuckets = (0x3f800000 >> kBucketShift) + 1;

struct BucketCodes {
    // 32-bit codes, not bytes: the row form's loop then gathers both tables
    // (about 2.5 times as fast as a byte table and two dependent steps,
    // on AVX-512; bench_draft, docs/design/performance.md).
    std::array<std::int32_t, kBuckets> code{};
    std::array<float, kBuckets> next{};  // the threshold above `code`; infinity above 254
};

BucketCodes makeBucketCodes() {
    BucketCodes b;
    for (int i = 0; i < kBuckets; ++i) {
        const std::uint32_t bits = static_cast<std::uint32_t>(i) << kBucketShift;
        float x;
        std::memcpy(&x, &bits, sizeof x);
        int code = 0;
        while (code < 255 && x >= kThresholds[code]) ++code;
        b.code[i] = code;
        b.next[i] = code < 255 ? kThresholds[code] : std::numeric_limits<float>::infinity();
    }
    return b;
}

const BucketCodes kBucketCodes = makeBucketCodes();

// srgbEncode() at the smallest float of each bucket, and 1.0 past the last:
// 1.0 itself is the last bucket's start, and its step to the next is zero.
std::array<float, kBuckets + 1> makeBucketStarts() {
    std::array<float, kBuckets + 1> starts{};
    for (int b = 0; b < kBuckets; ++b) {
        const std::uint32_t bits = static_cast<std::uint32_t>(b) << kBucketShift;
        float x;
        std::memcpy(&x, &bits, sizeof x);
        starts[b] = srgbEncode(x);
    }
    starts[kBuckets] = 1.0f;
    return starts;
}

const std::array<float, kBuckets + 1> kBucketStarts = makeBucketStarts();

}  // namespace

namespace {

// Without branches, so that the row form's loop gathers from the table:
// negative values and NaNs (as unsigned bits, above infinity's) become 0,
// and values of 1.0 and over become 1.0, whose bucket starts at its own
// value with no step to the next. A select on `linear > 0` instead, as encode8() has, leaves
// GCC 12 a branch it does not vectorise here.
inline float encodeFast(float linear) {
    std::uint32_t bits;
    std::memcpy(&bits, &linear, sizeof bits);
    bits = std::min(bits, 0x3f800000u) & (bits > 0x7f800000u ? 0u : ~0u);
    const std::int32_t bucket = std::int32_t(bits >> kBucketShift);
    // Within a bucket the mantissa's low bits step the value evenly.
    const float t =
        float(std::int32_t(bits & ((1u << kBucketShift) - 1))) * (1.0f / float(1u << kBucketShift));
    const float start = kBucketStarts[bucket], next = kBucketStarts[bucket + 1];
    return start + t * (next - start);
}

}  // namespace

float srgbEncodeFast(float linear) {
    return encodeFast(linear);
}

void srgbEncodeFast(const float* linear, std::size_t count, float* encoded) {
    for (std::size_t i = 0; i < count; ++i) encoded[i] = encodeFast(linear[i]);
}

namespace {

// Without branches on the value: values outside (0, 1] (and NaN) become 0 or
// 1, then the bucket's code and one comparison with the next threshold.
inline std::uint8_t encode8(float linear) {
    std::uint32_t bits;
    std::memcpy(&bits, &linear, sizeof bits);
    bits = linear > 0.0f ? std::min(bits, 0x3f800000u) : 0u;
    float clamped;
    std::memcpy(&clamped, &bits, sizeof clamped);
    const std::uint32_t bucket = bits >> kBucketShift;
    const int code = kBucketCodes.code[bucket] + (clamped >= kBucketCodes.next[bucket] ? 1 : 0);
    return static_cast<std::uint8_t>(code);
}

}  // namespace

std::uint8_t srgbEncode8(float linear) {
    return encode8(linear);
}

void srgbEncode8(const float* linear, std::size_t count, std::uint8_t* codes) {
    for (std::size_t i = 0; i < count; ++i) codes[i] = encode8(linear[i]);
}

float srgbDecode8(std::uint8_t code) {
    return srgbDecode(code / 255.0f);
}

}  // namespace whitted
