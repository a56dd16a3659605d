// The generated fields that test_quality_target renders to each preset, and
// the names their converged references are kept under (make_quality_references
// makes them before the test's cases run, analysis/reference_cache.h).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "analysis/reference_cache.h"
#include "sphere_field.h"

namespace whitted::test {

inline constexpr std::uint32_t kQualityFields = 4;

// Dense fields in front of the camera, 128x96: a few to a few hundred balls,
// a fifth of them glass and a fifth mirrors. Seeds 1 to kQualityFields.
inline Scene qualityField(std::uint32_t seed) {
    return sphereField({.count = 20 + 60 * int(seed),
                        .seed = 100 + seed,
                        .halfWidth = 2.0 + seed,
                        .depth = 6.0 + 2.0 * seed},
                       128, 96);
}

inline std::string qualityFieldName(std::uint32_t seed) {
    return "quality-field" + std::to_string(seed);
}

// Where its converged reference is kept (empty without WHITTED_REFERENCE_CACHE).
inline std::filesystem::path qualityFieldReferenceFile(std::uint32_t seed) {
    return cachedReferenceFile(qualityField(seed), qualityFieldName(seed));
}

// Its converged reference, from WHITTED_REFERENCE_CACHE's folder when that
// is set (made there if missing), rendered here otherwise.
inline Image qualityFieldReference(std::uint32_t seed) {
    return cachedReference(qualityField(seed), qualityFieldName(seed));
}

}  // namespace whitted::test
