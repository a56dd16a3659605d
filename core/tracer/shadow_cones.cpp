// A ray from p meets the sphere (centre c, radius r) on its way to the light
// L only if the line from L through p passes within r of c, that is if the
// direction from p to L is within asin(r / |L - c|) of the direction from c
// to L. Computed in double and widened, so that a shadow ray outside the cone
// is one the float sphere test would report as a miss.
#include "tracer/shadow_cones.h"

#include <cmath>

#include "tracer/screen_boxes.h"

namespace whitted {
namespace {

// A float dot product of unit vectors is off by a few 1e-8: the cosine is
// lowered by more, so that no ray in the cone compares below it.
constexpr double kCosineSlack = 4e-6;

}  // namespace

template <typename T>
std::vector<ShadowCone<T>> shadowCones(const Vec<T>& light, const SphereSet<T>& spheres) {
    std::vector<ShadowCone<T>> cones(spheres.count());
    for (int k = 0; k < spheres.count(); ++k) {
        const glm::dvec3 toLight = glm::dvec3(light) - spheres.centreOf(k);
        const double distance = glm::length(toLight);
        const double radius = spheres.radiusOf(k);
        const double reach = radius + kSkipWidening * (distance + radius);
        if (!(distance > reach)) {
            cones[k] = {Vec<T>(T(0)), T(-2)};  // below any rounded dot product
            continue;
        }
        const double sine = reach / distance;
        const double cosine = std::sqrt((1.0 - sine) * (1.0 + sine)) - kCosineSlack;
        T below = T(cosine);
        if (double(below) > cosine) below = std::nextafter(below, T(-1));
        cones[k] = {Vec<T>(toLight / distance), below};
    }
    return cones;
}

template std::vector<ShadowCone<float>> shadowCones(const Vec<float>&, const SphereSet<float>&);
template std::vector<ShadowCone<double>> shadowCones(const Vec<double>&, const SphereSet<double>&);

}  // namespace whitted
