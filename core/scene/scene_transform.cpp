#include "scene/scene_transform.h"

namespace whitted {

Scene scaledScene(const Scene& scene, double factor) {
    Scene s = scene;
    s.camera.position *= factor;
    s.camera.lookAt *= factor;
    for (Sphere& sp : s.spheres) {
        sp.center *= factor;
        sp.radius *= factor;
    }
    for (Light& l : s.lights) l.position *= factor;
    for (Material& m : s.materials)
        if (m.checker) m.checker->size *= factor;
    return s;
}

Scene translatedScene(const Scene& scene, const Vec3& offset) {
    Scene s = scene;
    s.camera.position += offset;
    s.camera.lookAt += offset;
    for (Sphere& sp : s.spheres) sp.center += offset;
    for (Light& l : s.lights) l.position += offset;
    return s;
}

}  // namespace whitted
