// whitted-field: writes a field of N balls on the checker floor as a scene
// file (issue 12), the scene bench_scaling times; scenes/field.json is one.
// Exit codes as whitted-render's: 0 success; 2 bad flags; 1 any other failure.
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>

#include <CLI/CLI.hpp>

#include "cli_main.h"
#include "scene/scene_io.h"
#include "sphere_field.h"

int main(int argc, char** argv) {
    whitted::FieldOptions field;
    std::string output;
    CLI::App app{
        "Write a scene of N small matte, mirror and glass balls on the seed's checker "
        "floor (the field bench_scaling renders).",
        "whitted-field"};
    app.add_option("count", field.count, "Number of balls, besides the floor")
        ->required()
        ->check(CLI::Range(0, 100'000'000));
    app.add_option("-o,--output", output, "Scene file to write (JSON)")->required();
    app.add_option("--seed", field.seed, "Random seed; the same flags give the same file")
        ->capture_default_str();
    app.add_option("--half-width", field.halfWidth, "Ball centres have |x| <= this")
        ->capture_default_str()
        ->check(CLI::PositiveNumber);
    app.add_option("--near", field.nearZ, "Nearest ball centres' z (the camera is at z = -1)")
        ->capture_default_str();
    app.add_option("--length", field.depth, "Ball centres have z from --near to --near + this")
        ->capture_default_str()
        ->check(CLI::PositiveNumber);
    if (const auto code = whitted::parseFlags(app, "whitted-field", argc, argv)) return *code;
    return whitted::runOrSay("whitted-field", [&] {
        whitted::saveScene(whitted::sphereField(field), output);
        return whitted::kExitOk;
    });
}
