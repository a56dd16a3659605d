// Command-line pieces the benchmark programs share.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>
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

// The CSV file a benchmark writes its rows to, its header line written; none
// for an empty path. A file that cannot be made ends the program (exit code 1).
inline std::FILE* openCsv(const std::string& path, const char* header) {
    if (path.empty()) return nullptr;
    std::FILE* csv = std::fopen(path.c_str(), "w");
    if (!csv) {
        std::perror(path.c_str());
        std::exit(1);
    }
    std::fprintf(csv, "%s\n", header);
    return csv;
}

}  // namespace whitted::bench
