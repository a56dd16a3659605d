// whitted-field: writes a field of N balls on the checker floor as a scene
// file, in one of the layouts bench_scaling times (field_layouts.h);
// scenes/field.json is one.
// Exit codes as whitted-render's: 0 success; 2 bad flags; 1 any other failure.
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli_main.h"
#include "field_layouts.h"
#include "scene/scene_io.h"

namespace {

std::string layoutHelp() {
    std::string help = "Where the balls go and the camera looks from:";
    for (const whitted::FieldLayout& l : whitted::fieldLayouts())
        help += "\n  " + l.name + ": " + l.description;
    return help;
}

}  // namespace

int main(int argc, char** argv) {
    int count = 0;
    std::string layout = "field", output;
    std::uint32_t seed = 1;
    double halfWidth = 0, nearZ = 0, depth = 0;
    CLI::App app{
        "Write a scene of N small matte, mirror and glass balls on the seed's checker "
        "floor (the fields bench_scaling renders).",
        "whitted-field"};
    app.add_option("count", count, "Number of balls, besides the floor")
        ->required()
        ->check(CLI::Range(0, 100'000'000));
    app.add_option("-o,--output", output, "Scene file to write (JSON)")->required();
    app.add_option("--layout", layout, layoutHelp())
        ->capture_default_str()
        ->check(CLI::IsMember(whitted::fieldLayoutNames()));
    app.add_option("--seed", seed, "Random seed; the same flags give the same file")
        ->capture_default_str();
    auto* halfWidthFlag =
        app.add_option("--half-width", halfWidth, "Ball centres have |x| <= this (field: 50)")
            ->check(CLI::PositiveNumber);
    auto* nearFlag = app.add_option(
        "--near", nearZ, "Nearest ball centres' z (the camera is at z = -1; field: 1.5)");
    auto* lengthFlag =
        app.add_option("--length", depth,
                       "Ball centres have z from --near to --near + this (field: 98.5)")
            ->check(CLI::PositiveNumber);
    if (const auto code = whitted::parseFlags(app, "whitted-field", argc, argv)) return *code;
    whitted::FieldOptions field = *whitted::fieldLayout(layout, count);
    field.seed = seed;
    if (*halfWidthFlag) field.halfWidth = halfWidth;
    if (*nearFlag) field.nearZ = nearZ;
    if (*lengthFlag) field.depth = depth;
    return whitted::runOrSay("whitted-field", [&] {
        whitted::saveScene(whitted::sphereField(field), output);
        return whitted::kExitOk;
    });
}
