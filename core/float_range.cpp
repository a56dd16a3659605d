#include "float_range.h"

#include <cmath>
#include <sstream>

#include <glm/geometric.hpp>

namespace whitted {

namespace {

// The edges of the measured range (docs/numerics.md, `whitted-numerics`): the
// seed scene renders right in float when scaled by 10^k for k in [-20, 14];
// there its shortest length (the checker size) is 5e-21 and its longest reach
// from the camera (the floor) 2.0e19. Beyond, squared lengths leave float's
// normal range (1.2e-38 .. 3.4e38) and the picture falls apart. Translation does
// not matter: the tracer works relative to the camera.
constexpr double kShortest = 4.9e-21;
constexpr double kLongest = 2.1e19;

std::string number(double v) {
    std::ostringstream s;
    s.precision(2);
    s << v;
    return s.str();
}

}  // namespace

std::optional<std::string> floatRangeProblem(const Scene& scene) {
    const Vec3 eye = scene.camera.position;
    double longest = 0.0, shortest = INFINITY;
    std::string longestWhat, shortestWhat;
    auto reach = [&](double v, std::string what) {
        if (v > longest) longest = v, longestWhat = std::move(what);
    };
    auto size = [&](double v, std::string what) {
        if (v < shortest) shortest = v, shortestWhat = std::move(what);
    };
    for (const Sphere& s : scene.spheres) {
        reach(glm::length(s.center - eye) + s.radius, "sphere \"" + s.name + "\" reaches");
        size(s.radius, "the radius of sphere \"" + s.name + "\"");
    }
    for (const Light& l : scene.lights)
        reach(glm::length(l.position - eye), "light \"" + l.name + "\" lies");
    for (const Material& m : scene.materials)
        if (m.checker) size(m.checker->size, "the checker size of material \"" + m.name + "\"");
    if (longest > kLongest)
        return longestWhat + " " + number(longest) +
               " from the camera; float is measured right only up to 2e+19";
    if (shortest < kShortest)
        return shortestWhat + " is " + number(shortest) +
               "; float is measured right only down to 5e-21";
    return std::nullopt;
}

}  // namespace whitted
