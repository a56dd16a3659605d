// What a farm render consists of (whitted-farm): one task for each
// region or frame, each a whitted-render command line and the file it writes,
// and for regions a merge. Plain values; the submission is slurm.h's.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "image/image.h"

namespace whitted::farm {

struct Task {
    std::vector<std::string> argv;  // the whole command, program first
    std::filesystem::path output;   // what it writes, atomically: there means done
};

struct Plan {
    std::optional<Task> prepare;  // before every task: what they share (a render's plan)
    std::vector<Task> tasks;      // one array task each, finished or not
    std::optional<Task> merge;    // after every task: the regions put together
};

// `tiles` regions covering a width x height image: a grid of about square
// cells, ceil(sqrt(tiles)) columns, the last row's cells as wide as it takes.
std::vector<PixelRect> tileRegions(int width, int height, int tiles);

// What every task renders: the program, the scene and the flags that override
// its settings, which every task passes on alike.
struct RenderCommand {
    std::string program;  // whitted-render
    std::string scene;
    std::vector<std::string> overrides;
};

// The regions of `output`, as parts in `work` (part.K.exr), and their merge.
Plan regionPlan(const RenderCommand& command, const std::filesystem::path& output,
                const std::filesystem::path& work, int width, int height, int tiles);

// The frames of a turntable, each written as whitted-render names it.
Plan turntablePlan(const RenderCommand& command, const std::filesystem::path& output, int frames);

}  // namespace whitted::farm
