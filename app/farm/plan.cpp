#include "plan.h"

#include <cmath>
#include <string>

#include "image/image_files.h"

namespace whitted::farm {

namespace fs = std::filesystem;

std::vector<PixelRect> tileRegions(int width, int height, int tiles) {
    const int columns = static_cast<int>(std::ceil(std::sqrt(double(tiles))));
    const int rows = (tiles + columns - 1) / columns;
    std::vector<PixelRect> regions;
    for (int r = 0; r < rows; ++r) {
        const int y0 = height * r / rows, y1 = height * (r + 1) / rows;
        const int cells = r + 1 < rows ? columns : tiles - columns * (rows - 1);
        for (int c = 0; c < cells; ++c) {
            const int x0 = width * c / cells, x1 = width * (c + 1) / cells;
            regions.push_back({x0, y0, x1 - x0, y1 - y0});
        }
    }
    return regions;
}

namespace {

std::vector<std::string> renderArgs(const RenderCommand& command, const fs::path& output) {
    std::vector<std::string> argv = {command.program, command.scene, "-o", output.string()};
    argv.insert(argv.end(), command.overrides.begin(), command.overrides.end());
    argv.push_back("--quiet");
    return argv;
}

}  // namespace

Plan regionPlan(const RenderCommand& command, const fs::path& output, const fs::path& work,
                int width, int height, int tiles) {
    Plan plan;
    Task merge{{command.program, "merge"}, output};
    for (const PixelRect& r : tileRegions(width, height, tiles)) {
        const fs::path part = work / ("part." + std::to_string(plan.tasks.size()) + ".exr");
        Task task{renderArgs(command, part), part};
        task.argv.insert(task.argv.end(), {"--region", cornersText(r)});
        plan.tasks.push_back(task);
        merge.argv.push_back(part.string());
    }
    merge.argv.insert(merge.argv.end(), {"-o", output.string(), "--quiet"});
    plan.merge = merge;
    return plan;
}

Plan turntablePlan(const RenderCommand& command, const fs::path& output, int frames) {
    Plan plan;
    for (int frame = 1; frame <= frames; ++frame) {
        Task task{renderArgs(command, output), frameFile(output, frame)};
        const std::string n = std::to_string(frame);
        task.argv.insert(task.argv.end(),
                         {"--turntable", std::to_string(frames), "--frames", n + "-" + n});
        plan.tasks.push_back(task);
    }
    return plan;
}

}  // namespace whitted::farm
