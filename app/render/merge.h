// `whitted-render merge`: the regions of one picture (--region parts, OpenEXR
// files that record where they belong) put back together into one image.
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace whitted {

struct MergeOptions {
    std::vector<std::string> parts;
    std::string output;
    bool quiet = false;
};

// The subcommand and its flags, into `options`.
CLI::App* addMergeCommand(CLI::App& app, MergeOptions& options);

// The parts read, checked to tile one picture, and written as one image:
// the exit code, having said what went wrong.
int runMerge(const MergeOptions& options);

}  // namespace whitted
