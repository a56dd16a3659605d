// Command-line pieces the benchmark programs share.
#pragma once

#include <cstdlib>
#include <vector>

namespace whitted::bench {

// "100,1000,10000" -> {100, 1000, 10000}: the scene sizes to run.
inline std::vector<int> parseSizes(const char* p) {
    std::vector<int> sizes;
    while (*p) {
        char* end;
        sizes.push_back(static_cast<int>(std::strtol(p, &end, 10)));
        p = *end ? end + 1 : end;
    }
    return sizes;
}

}  // namespace whitted::bench
