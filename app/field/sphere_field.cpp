#include "sphere_field.h"

#include <random>
#include <string>

namespace whitted {

namespace {

void addMaterials(Scene& s) {
    s.materials = {
        {"blue", {0, 0, 1}, 1, 50, 0.5, 0, 1.5, {}},
        {"purple", {0.5, 0, 0.5}, 1, 50, 0.5, 0, 1.5, {}},
        {"white", {1, 0.99, 0.99}, 1, 50, 0.5, 0, 1.5, {}},
        {"mirror", {0.1, 0.1, 0.1}, 1, 60, 0.8, 0, 1.5, {}},
        {"glass", {0, 0, 0}, 1, 200, 0.1, 0.9, 1.5, {}},
        {"floor", {0.75, 0.75, 0.75}, 1, 50, 0.25, 0, 1.5, Checker{{0, 0, 0}, 0.5}},
    };
}

}  // namespace

Scene sphereField(const FieldOptions& o) {
    Scene s;
    s.camera = {{0, 0.35, -1}, {0, 0.25, 0}, {0, 1, 0}, 73.74};
    s.render.maxDepth = 5;
    s.background = {0.002, 0.002, 0.004};
    addMaterials(s);
    s.lights = {{"key", {5, 5, -10}, {1, 1, 1}, 1}};
    std::mt19937 rng(o.seed);
    std::uniform_real_distribution<double> x(-o.halfWidth, o.halfWidth);
    std::uniform_real_distribution<double> z(o.nearZ, o.nearZ + o.depth), r(0.05, 0.3);
    const char* materials[] = {"blue", "purple", "white", "mirror", "glass"};
    s.spheres.reserve(std::size_t(o.count) + 1);
    for (int i = 0; i < o.count; ++i) {
        // Separate statements: the draws must come in this order on every compiler.
        const double radius = r(rng);
        const double cx = x(rng);
        const double cz = z(rng);
        s.spheres.push_back(
            {"ball " + std::to_string(i), {cx, -0.5 + radius, cz}, radius, materials[i % 5]});
    }
    s.spheres.push_back({"floor", {0, -99999.5, 0}, 99999, "floor"});
    return s;
}

Scene sphereField(const FieldOptions& options, int width, int height) {
    Scene s = sphereField(options);
    s.render.width = width;
    s.render.height = height;
    return s;
}

FieldOptions untunedField(int n) {
    FieldOptions o;
    o.count = 40 + 37 * (n % 9);
    o.seed = 500 + std::uint32_t(n);
    o.halfWidth = 2.0 + n % 4;
    o.depth = 5.0 + 1.5 * (n % 5);
    return o;
}

}  // namespace whitted
