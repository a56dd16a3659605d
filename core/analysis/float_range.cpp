#include "analysis/float_range.h"

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
    // What is longest and shortest is worded only at the end: the editor asks
    // on every edit, and words for each of 100,000 spheres took milliseconds.
    enum class What { Sphere, Light, Checker };
    double longest = 0.0, shortest = INFINITY;
    What longestWhat = What::Sphere, shortestWhat = What::Sphere;
    size_t longestAt = 0, shortestAt = 0;
    auto reach = [&](double v, What what, size_t at) {
        if (v > longest) longest = v, longestWhat = what, longestAt = at;
    };
    auto size = [&](double v, What what, size_t at) {
        if (v < shortest) shortest = v, shortestWhat = what, shortestAt = at;
    };
    for (size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& s = scene.spheres[i];
        reach(glm::length(s.center - eye) + s.radius, What::Sphere, i);
        size(s.radius, What::Sphere, i);
    }
    for (size_t i = 0; i < scene.lights.size(); ++i)
        reach(glm::length(scene.lights[i].position - eye), What::Light, i);
    for (size_t i = 0; i < scene.materials.size(); ++i)
        if (const auto& checker = scene.materials[i].checker) size(checker->size, What::Checker, i);
    if (longest > kLongest) {
        const std::string what = longestWhat == What::Sphere
                                     ? "sphere \"" + scene.spheres[longestAt].name + "\" reaches"
                                     : "light \"" + scene.lights[longestAt].name + "\" lies";
        return what + " " + number(longest) +
               " from the camera; float is measured right only up to 2e+19";
    }
    if (shortest < kShortest) {
        const std::string what =
            shortestWhat == What::Sphere
                ? "the radius of sphere \"" + scene.spheres[shortestAt].name + "\""
                : "the checker size of material \"" + scene.materials[shortestAt].name + "\"";
        return what + " is " + number(shortest) + "; float is measured right only down to 5e-21";
    }
    return std::nullopt;
}

}  // namespace whitted
