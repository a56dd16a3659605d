// Scene size against render time: a field of N small matte, mirror
// and glass spheres on the seed's checker floor (app/field/sphere_field.h),
// rendered in one run by our tracer in float and double, by brute force, and,
// when built with Embree 3, by the Embree tracer of embree_tracer.h. Prints
// build time, render time and Mrays/s for each; not a test.
//   build/bin/bench_scaling [--sizes N,N,...] [--width W] [--height H]
//                           [--max-brute N] [--no-double] [--bvh] [--csv FILE]
//                           [--images DIR] [--layouts NAME,NAME,...] [--embree-only]
//   build/bin/bench_scaling WIDTH HEIGHT [MAX_BRUTE_N [N,N,...]]   (older form)
// Defaults: 1280x720, N = 4,100,1000,10000,100000,1000000, brute force only up
// to 10000 spheres (100k takes minutes). 1 spp, depth 5, 2 threads. Build
// times are the best of three builds alone; render times include scene
// preparation and the build, Embree's too. "ours" is the tracer's own choice
// of structure (brute force below kBvhCrossover spheres, the BVH above); with
// --bvh, and in the older form, whose crossover figures in docs/design/acceleration.md
// compare the two at every N, it is always the BVH. "kept" is a float render
// after another with the same BvhCache and the camera nudged: the tree kept and
// refit whole, as in the editor after a camera move. --images writes our float
// render and Embree's as DIR/field-N-ours.png and DIR/field-N-embree.png, to
// look at what the PSNR column summarises. --layouts times other fields than
// the one the tracer was tuned on (app/field/field_layouts.h; default "field").
// --embree-only leaves our renders out (their columns -1), for a profile of
// Embree's render alone; whitted-render on the same scene file profiles ours.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "base/elapsed.h"
#include "bench_args.h"
#include "field_layouts.h"
#include "image/image_error.h"
#include "image/image_io.h"
#include "tracer/bvh.h"
#include "tracer/kernel_dispatch.h"
#include "tracer/renderer.h"
#ifdef WHITTED_HAVE_EMBREE
#include <embree3/rtcore_config.h>

#include "embree_tracer.h"
#endif

namespace {

using namespace whitted;

constexpr int kThreads = 2;

struct Options {
    int width = 1280, height = 720;
    int maxBrute = 10000;
    std::vector<int> sizes = {4, 100, 1000, 10000, 100000, 1000000};
    bool doubles = true;
    Acceleration ours = Acceleration::automatic;
    std::string csv;
    std::string images;
    std::vector<std::string> layouts = {"field"};
    bool embreeOnly = false;
};

Options parseOptions(int argc, char** argv) {
    Options o;
    CLI::App app{"Scene size against render time, ours against Embree (see the source's top)"};
    app.add_option("--sizes", o.sizes, "Sphere counts, e.g. 100,1000")->delimiter(',');
    app.add_option("--width", o.width, "Image width");
    app.add_option("--height", o.height, "Image height");
    app.add_option("--max-brute", o.maxBrute, "Brute force only up to this many spheres");
    app.add_flag("!--no-double", o.doubles, "Leave double precision out");
    bool bvh = false;
    app.add_flag("--bvh", bvh, "Ours always with the BVH, not its own choice");
    app.add_option("--csv", o.csv, "Write the table as CSV");
    app.add_option("--images", o.images, "Write our render and Embree's into this folder");
    app.add_flag("--embree-only", o.embreeOnly,
                 "Render with Embree alone (to profile it: whitted-render profiles ours)");
    app.add_option("--layouts", o.layouts, "Field layouts, e.g. field,clustered")
        ->delimiter(',')
        ->check(CLI::IsMember(fieldLayoutNames()));
    // The older form: WIDTH HEIGHT [MAX_BRUTE_N [N,N,...]], always the BVH.
    std::vector<std::string> older;
    app.add_option("older", older, "WIDTH HEIGHT [MAX_BRUTE_N [N,N,...]] (older form)")
        ->expected(0, 4);
    try {
        app.parse(argc, argv);
        if (!older.empty()) {
            if (older.size() < 2) throw CLI::ValidationError("older form", "WIDTH HEIGHT");
            o.width = std::stoi(older[0]);
            o.height = std::stoi(older[1]);
            if (older.size() > 2) o.maxBrute = std::stoi(older[2]);
            if (older.size() > 3) o.sizes = bench::parseSizes(older[3].c_str());
            bvh = true;
        }
    } catch (const CLI::ParseError& e) {
        std::exit(app.exit(e) == 0 ? 0 : 2);  // help: 0; a bad flag: 2, as before
    }
    if (bvh) o.ours = Acceleration::bvh;
    return o;
}

struct Run {
    double ms = -1;  // -1: not run
    double mrays = 0;
    Image image;
};

Run renderWith(Scene scene, Acceleration choice, Precision precision, BvhCache* kept = nullptr) {
    scene.render.precision = precision;
    useAcceleration(choice);
    RenderOptions options = oneShotOptions();
    options.threads = kThreads;
    options.bvhCache = kept;
    RenderResult result = render(scene, options);
    useAcceleration(Acceleration::automatic);
    return {result.seconds * 1e3, double(result.rays.total()) / result.seconds / 1e6,
            std::move(result.image)};
}

struct Tree {
    double buildMs = 1e300;
    double bytesPerSphere = 0, doubleBytesPerSphere = 0;  // the float and the double tree
};

template <typename T>
double bytesPerSphere(const SphereBvh<T>& bvh, std::size_t spheres) {
    const std::size_t bytes = bvh.nodes.size() * sizeof(BvhNode) +
                              bvh.leafSpheres.size() * sizeof(LeafSphere<T>) +
                              bvh.direct.size() * sizeof(std::int32_t);
    return double(bytes) / double(spheres);
}

// Our float tree alone: the best of three builds; and the bytes of its nodes
// and leaf arrays, and of the double tree's.
Tree measureTree(const Scene& scene) {
    std::vector<glm::dvec3> centres;
    std::vector<double> radii;
    for (const Sphere& sp : scene.spheres) {
        centres.push_back(sp.center - scene.camera.position);
        radii.push_back(sp.radius);
    }
    Tree tree;
    for (int i = 0; i < 3; ++i) {
        const auto start = std::chrono::steady_clock::now();
        const SphereBvh<float> bvh = buildSphereBvh<float>(centres, radii);
        tree.buildMs = std::min(tree.buildMs, 1e3 * secondsSince(start));
        tree.bytesPerSphere = bytesPerSphere(bvh, scene.spheres.size());
    }
    tree.doubleBytesPerSphere =
        bytesPerSphere(buildSphereBvh<double>(centres, radii), scene.spheres.size());
    return tree;
}

struct Peer {
    double buildHighMs = -1, buildMediumMs = -1;
    Run run;
    double psnr = 0;  // of the peer's 8-bit sRGB image against ours, dB
    Image image;
};

Peer embreeRun([[maybe_unused]] const Scene& scene, [[maybe_unused]] const Image& ours) {
    Peer peer;
#ifdef WHITTED_HAVE_EMBREE
    EmbreeRun e = renderWithEmbree(scene, kThreads);
    peer.buildHighMs = e.buildHighMs;
    peer.buildMediumMs = e.buildMediumMs;
    peer.run.ms = e.renderMs;
    peer.run.mrays = double(e.rays.total()) / e.renderMs / 1e3;
    if (!ours.rgb.empty()) peer.psnr = measureError(e.image, ours).psnrSrgb8;
    peer.image = std::move(e.image);
#endif
    return peer;
}

// "-" for a figure that was not measured.
std::string cell(double value, const char* format, bool measured) {
    if (!measured) return "-";
    char text[32];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

struct Row {
    std::string layout;
    int n;
    Tree tree;
    Run ours, doubles, brute;
    // A render with the tree of the render before kept and refit, as the
    // editor renders after an edit or a camera move.
    Run kept;
    Peer embree;
};

void printHeader() {
    std::printf("%-9s %8s %9s %7s %7s | %10s %8s %9s %10s %8s %10s | %9s %9s %10s %8s %7s %6s\n",
                "layout", "N", "build ms", "B/sph", "B/sph d", "float ms", "Mr/s", "kept ms",
                "double ms", "dbl/flt", "brute ms", "E high ms", "E med ms", "Embree ms", "E Mr/s",
                "ours/E", "PSNR");
}

void printRow(const Row& r) {
    const bool e = r.embree.run.ms >= 0, d = r.doubles.ms >= 0;
    std::printf(
        "%-9s %8d %9.2f %7.1f %7.1f | %10.1f %8.2f %9.1f %10s %8s %10s | %9s %9s %10s %8s %7s "
        "%6s\n",
        r.layout.c_str(), r.n, r.tree.buildMs, r.tree.bytesPerSphere, r.tree.doubleBytesPerSphere,
        r.ours.ms, r.ours.mrays, r.kept.ms, cell(r.doubles.ms, "%.1f", d).c_str(),
        cell(r.doubles.ms / r.ours.ms, "%.2f", d).c_str(),
        cell(r.brute.ms, "%.1f", r.brute.ms >= 0).c_str(),
        cell(r.embree.buildHighMs, "%.2f", e).c_str(),
        cell(r.embree.buildMediumMs, "%.2f", e).c_str(), cell(r.embree.run.ms, "%.1f", e).c_str(),
        cell(r.embree.run.mrays, "%.2f", e).c_str(),
        cell(r.ours.ms / r.embree.run.ms, "%.2f", e && r.ours.ms >= 0).c_str(),
        cell(r.embree.psnr, "%.1f", e && r.ours.ms >= 0).c_str());
    std::fflush(stdout);
}

void writeCsv(std::FILE* f, const Row& r) {
    std::fprintf(f, "%s,%d,%.3f,%.2f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.2f,%.2f,%.3f\n",
                 r.layout.c_str(), r.n, r.tree.buildMs, r.tree.bytesPerSphere, r.ours.ms,
                 r.ours.mrays, r.doubles.ms, r.brute.ms, r.embree.buildHighMs,
                 r.embree.buildMediumMs, r.embree.run.ms, r.embree.run.mrays,
                 r.embree.run.ms >= 0 && r.ours.ms >= 0 ? r.ours.ms / r.embree.run.ms : -1.0,
                 r.ours.ms >= 0 ? r.embree.psnr : -1.0, r.tree.doubleBytesPerSphere, r.kept.ms);
    std::fflush(f);
}

void saveImages(const std::string& dir, const Scene& scene, const Row& row) {
    const std::string stem = dir + "/" + row.layout + "-" + std::to_string(row.n);
    const ImageMetadata metadata =
        makeImageMetadata(scene.render, row.ours.ms / 1e3, "bench_scaling");
    writeImage(row.ours.image, stem + "-ours.png", metadata);
    if (row.embree.run.ms >= 0) writeImage(row.embree.image, stem + "-embree.png", metadata);
}

Row measureRow(const Options& o, const std::string& layout, const Scene& scene) {
    const int n = int(scene.spheres.size()) - 1;  // the floor is not counted
    Row row{layout, n, {}, {}, {}, {}, {}, {}};
    if (o.embreeOnly) {  // nothing of ours in the profile, not even the tree's build
        row.tree = Tree{-1, -1, -1};
        row.embree = embreeRun(scene, Image());
        return row;
    }
    row.tree = measureTree(scene);
    row.ours = renderWith(scene, o.ours, Precision::Float);
    BvhCache cache;
    renderWith(scene, o.ours, Precision::Float, &cache);
    // The camera nudged along its view, as a wheel step in the editor does:
    // the camera-centred frame moves, so every box is refit (with the
    // spheres and the frame as they were, the tree would be used as it is).
    Scene nudged = scene;
    nudged.camera.position += 1e-6 * (scene.camera.lookAt - scene.camera.position);
    row.kept = renderWith(nudged, o.ours, Precision::Float, &cache);
    if (o.doubles) row.doubles = renderWith(scene, o.ours, Precision::Double);
    if (n <= o.maxBrute) row.brute = renderWith(scene, Acceleration::bruteForce, Precision::Float);
    row.embree = embreeRun(scene, row.ours.image);
    return row;
}

}  // namespace

int main(int argc, char** argv) {
    const Options o = parseOptions(argc, argv);
    std::FILE* csv =
        bench::openCsv(o.csv,
                       "layout,n,build_ms,bytes_per_sphere,float_ms,float_mrays,double_ms,brute_ms,"
                       "embree_build_high_ms,embree_build_medium_ms,embree_ms,embree_mrays,"
                       "ours_over_embree,psnr_db,bytes_per_sphere_double,kept_ms");
    std::printf("field of N spheres + floor, %dx%d, 1 spp, depth 5, %d threads, kernel %s\n",
                o.width, o.height, kThreads, activeKernelName().c_str());
#ifdef WHITTED_HAVE_EMBREE
    std::printf("Embree %s: spheres as sphere points, floor in double; 16-wide camera packets\n",
                RTC_VERSION_STRING);
#else
    std::printf("Embree: not installed (apt-get install libembree-dev, then reconfigure)\n");
#endif
    std::printf("ours: %s; render ms include preparation and build; -1 in the CSV: not measured\n",
                o.ours == Acceleration::bvh ? "always the BVH" : "the tracer's own choice");
    printHeader();
    for (const std::string& layout : o.layouts)
        for (const int n : o.sizes) {
            const Scene scene = sphereField(*fieldLayout(layout, n), o.width, o.height);
            const Row row = measureRow(o, layout, scene);
            printRow(row);
            if (csv) writeCsv(csv, row);
            if (!o.images.empty()) saveImages(o.images, scene, row);
        }
    if (csv) std::fclose(csv);
    return 0;
}
