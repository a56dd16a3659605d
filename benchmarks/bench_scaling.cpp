// Scene size against render time (issue 12): a field of N small matte, mirror
// and glass spheres on the seed's checker floor, rendered by brute force and
// through the sphere BVH in one run. Prints build time, render time and
// Mrays/s for each; not a test.
//   build/bin/bench_scaling [WIDTH HEIGHT [MAX_BRUTE_N [N,N,...]]]
// (default 320 180 10000 4,100,1000,10000,100000). Brute force is skipped
// above MAX_BRUTE_N spheres (100k takes minutes). Build times are the best of
// three builds alone; render times include scene preparation (and the build).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "bvh.h"
#include "kernel_dispatch.h"
#include "renderer.h"
#include "scene_io.h"

namespace {

using namespace whitted;

// The seed's camera, light and floor; N balls resting on the floor in front
// of the camera (fixed seed: every run the same scene).
Scene field(int count) {
    Scene s = loadScene(WHITTED_SCENES_DIR "/seed.json");
    const Sphere floor = s.spheres.back();
    s.spheres.clear();
    Material mirror{"mirror", {0.1, 0.1, 0.1}, 1, 60, 0.8, 0, 1.5, {}};
    Material glass{"glass", {0, 0, 0}, 1, 200, 0.1, 0.9, 1.5, {}};
    s.materials.push_back(mirror);
    s.materials.push_back(glass);
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> x(-50, 50), z(1.5, 100), r(0.05, 0.3);
    const char* materials[] = {"blue", "purple", "white", "mirror", "glass"};
    for (int i = 0; i < count; ++i) {
        const double radius = r(rng);
        s.spheres.push_back({"ball " + std::to_string(i),
                             {x(rng), -0.5 + radius, z(rng)},
                             radius,
                             materials[i % 5]});
    }
    s.spheres.push_back(floor);
    s.render.maxDepth = 5;
    s.render.samplesPerPixel = 1;
    s.render.precision = Precision::Float;
    return s;
}

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

struct Run {
    double ms = 0;
    double mrays = 0;
};

Run renderWith(const Scene& scene, Acceleration choice) {
    useAcceleration(choice);
    RenderOptions options;
    options.threads = 2;
    options.progressive = false;
    const RenderResult result = render(scene, options);
    useAcceleration(Acceleration::automatic);
    return {result.seconds * 1e3, double(result.rays.total()) / result.seconds / 1e6};
}

}  // namespace

int main(int argc, char** argv) {
    const int width = argc > 2 ? std::atoi(argv[1]) : 320;
    const int height = argc > 2 ? std::atoi(argv[2]) : 180;
    const int maxBrute = argc > 3 ? std::atoi(argv[3]) : 10000;
    std::vector<int> counts = {4, 100, 1000, 10000, 100000};
    if (argc > 4) {
        counts.clear();
        for (const char* p = argv[4]; *p;) {
            char* end;
            counts.push_back(static_cast<int>(std::strtol(p, &end, 10)));
            p = *end ? end + 1 : end;
        }
    }
    std::printf("field of N spheres + floor, %dx%d, 1 spp, depth 5, float, 2 threads, kernel %s\n",
                width, height, activeKernelName().c_str());
    std::printf("%8s %10s %12s %12s %12s %12s %8s\n", "N", "build ms", "brute ms", "brute Mr/s",
                "bvh ms", "bvh Mr/s", "speedup");
    for (const int n : counts) {
        Scene scene = field(n);
        scene.render.width = width;
        scene.render.height = height;
        std::vector<glm::dvec3> centres;
        std::vector<double> radii;
        for (const Sphere& sp : scene.spheres) {
            centres.push_back(sp.center - scene.camera.position);
            radii.push_back(sp.radius);
        }
        double build = 1e300;
        for (int i = 0; i < 3; ++i) {
            const auto start = std::chrono::steady_clock::now();
            const SphereBvh<float> bvh = buildSphereBvh<float>(centres, radii);
            build = std::min(build, msSince(start));
        }
        const Run tree = renderWith(scene, Acceleration::bvh);
        if (n <= maxBrute) {
            const Run brute = renderWith(scene, Acceleration::bruteForce);
            std::printf("%8d %10.2f %12.1f %12.2f %12.1f %12.2f %7.1fx\n", n, build, brute.ms,
                        brute.mrays, tree.ms, tree.mrays, brute.ms / tree.ms);
        } else {
            std::printf("%8d %10.2f %12s %12s %12.1f %12.2f %8s\n", n, build, "-", "-", tree.ms,
                        tree.mrays, "-");
        }
        std::fflush(stdout);
    }
    return 0;
}
