// Renders the converged reference of one of test_quality_target's fields
// (its seed, the argument) into WHITTED_REFERENCE_CACHE's folder, replacing
// the one there: the CTest fixtures that run before that test's cases, so
// that each reference is rendered once a run (the largest field's takes
// 15 s) rather than once for each of its presets.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>

#include "support/quality_fields.h"

int main(int argc, char** argv) {
    const char* folder = std::getenv("WHITTED_REFERENCE_CACHE");
    const std::uint32_t seed = argc == 2 ? std::uint32_t(std::atoi(argv[1])) : 0;
    if (!folder || seed < 1 || seed > whitted::test::kQualityFields) {
        std::fprintf(stderr,
                     "usage: WHITTED_REFERENCE_CACHE=DIR make_quality_references SEED (1 to %u)\n",
                     whitted::test::kQualityFields);
        return 2;
    }
    try {
        std::filesystem::remove(whitted::test::qualityFieldReferenceFile(seed));
        whitted::test::qualityFieldReference(seed);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "make_quality_references: %s\n", e.what());
        return 1;
    }
    std::printf("field %u: reference made\n", seed);
    return 0;
}
