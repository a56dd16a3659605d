// Whitted's 1980 adaptive sampling (--sampler whitted1980) on the trade-off
// front against ours: fixed stratified samples (1 to 64 a pixel) and
// adaptive sampling to a target PSNR (30 to 50 dB), on every shipped scene and
// on generated fields, each against a converged reference at the scene's own
// depth (double, 256 samples), so that only the sampling differs. For each
// render: camera rays and all rays a pixel, seconds (the best of three, two
// threads) and the error (PSNR of the 8-bit picture, largest error in codes).
// `whitted-tradeoff --report --sampler-csv` sets each 1980 setting against the
// fastest of ours that is as good (docs/tradeoff.md).
//
// Usage: bench_whitted1980 [WIDTH [CSV [PICTURE]]] (default 160, the height
// three quarters of it). With CSV, the rows are also written there
// (benchmarks/whitted1980.csv keeps the published ones); with PICTURE, why the
// 1980 sampler stops short on the seed, as four panels side by side, each
// twice its size: its render (threshold 8, 2 cuts), the reference, the error
// of each pixel (the Precision Check's heat map) and how deep each pixel was
// cut (docs/tradeoff/whitted1980/why-seed.png).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "analysis/quality_check.h"
#include "base/csv_rows.h"
#include "bench_scenes.h"
#include "image/heat_map.h"
#include "image/image_error.h"
#include "image/image_io.h"
#include "tracer/renderer.h"

using namespace whitted;

namespace {

struct Row {
    std::string scene, sampler, setting;
    double cameraRaysPerPixel = 0, raysPerPixel = 0, seconds = 0, psnr = 0, largest = 0;
};

struct Sampler {
    std::string name, setting;
    RenderOptions options;
    int samples = 1;  // a fixed render's samples a pixel
};

std::vector<Sampler> samplers() {
    std::vector<Sampler> list;
    for (int spp : {1, 4, 16, 64}) {
        Sampler s{"fixed", std::to_string(spp) + " spp", oneShotOptions(), spp};
        list.push_back(s);
    }
    for (double psnr : {30.0, 35.0, 40.0, 45.0, 50.0}) {
        Sampler s{"adaptive", "to " + std::to_string(int(psnr)) + " dB", oneShotOptions()};
        AdaptiveSampling limits;
        limits.allowedMse = 255.0 * 255.0 * std::pow(10.0, -psnr / 10.0);
        limits.maxSamples = 256;
        s.options.adaptive = limits;
        list.push_back(s);
    }
    for (const auto& [threshold, levels] :
         {std::pair{16.0, 1}, {8.0, 2}, {4.0, 2}, {4.0, 3}, {2.0, 3}, {1.0, 4}}) {
        char setting[64];
        std::snprintf(setting, sizeof setting, "threshold %g, %d cut%s", threshold, levels,
                      levels == 1 ? "" : "s");
        Sampler s{"whitted1980", setting, oneShotOptions()};
        s.options.whitted1980 = Whitted1980Sampling{threshold, levels};
        list.push_back(s);
    }
    return list;
}

Row measure(const NamedScene& named, const Sampler& sampler, const Image& reference) {
    Scene scene = named.scene;
    scene.render.samplesPerPixel = sampler.samples;
    RenderOptions options = sampler.options;
    options.threads = 2;
    Row row{named.name, sampler.name, sampler.setting};
    double best = std::numeric_limits<double>::infinity();
    RenderResult result;
    for (int run = 0; run < 3; ++run) {
        result = render(scene, options);
        best = std::min(best, result.seconds);
    }
    const double pixels = double(scene.render.width) * scene.render.height;
    row.cameraRaysPerPixel = double(result.rays.camera) / pixels;
    row.raysPerPixel = double(result.rays.total()) / pixels;
    row.seconds = best;
    const ErrorStats error = measureError(result.image, reference);
    row.psnr = error.psnrSrgb8;
    row.largest = error.largest;
    return row;
}

void printScene(const std::vector<Row>& rows) {
    std::printf("\n### %s\n\n", rows.front().scene.c_str());
    std::printf(
        "| sampler | setting | camera rays/px | rays/px | ms | PSNR dB | largest codes "
        "|\n|---|---|---|---|---|---|---|\n");
    for (const Row& row : rows)
        std::printf("| %s | %s | %.2f | %.1f | %.1f | %.1f | %.0f |\n", row.sampler.c_str(),
                    row.setting.c_str(), row.cameraRaysPerPixel, row.raysPerPixel,
                    row.seconds * 1e3, row.psnr, row.largest);
    std::fflush(stdout);
}

// `panel` at twice its size into `into` from column `x`.
void paste(const Image& panel, Image& into, int x) {
    for (int y = 0; y < into.height; ++y)
        for (int dx = 0; dx < 2 * panel.width; ++dx)
            std::copy_n(panel.pixel(dx / 2, y / 2), 3, into.pixel(x + dx, y));
}

void writeWhy(const Scene& scene, const Image& reference, const std::string& file) {
    RenderOptions options = oneShotOptions();
    options.whitted1980 = Whitted1980Sampling{8.0, 2};
    const RenderResult result = render(scene, options);
    const int w = scene.render.width, h = scene.render.height;
    Image why(8 * w, 2 * h);
    paste(result.image, why, 0);
    paste(reference, why, 2 * w);
    paste(heatMap(result.image, reference), why, 4 * w);
    paste(countMap(result.subdivision.levels, w, h, 2), why, 6 * w);
    writeImage(why, file, {});
}

}  // namespace

int main(int argc, char** argv) {
    const int width = argc > 1 ? std::atoi(argv[1]) : 160;
    const int height = width * 3 / 4;
    std::ofstream csv;
    if (argc > 2) {
        csv.open(argv[2]);
        csv << "scene,sampler,setting,width,height,camera_rays_per_pixel,rays_per_pixel,seconds,"
               "psnr_db,largest_codes\n";
    }
    std::printf(
        "Whitted 1980 sampling against ours at %dx%d, float, 2 threads; references: "
        "double, 256 samples, the scene's depth\n",
        width, height);
    const std::vector<NamedScene> scenes =
        benchScenes(width, height,
                    {generatedField(150, 31, 4.0, 10.0), generatedField(400, 57, 4.0, 10.0),
                     generatedField(2000, 5, 20.0, 60.0)});
    for (const NamedScene& named : scenes) {
        const Image reference = convergedReference(named.scene, 256, named.scene.render.maxDepth);
        std::vector<Row> rows;
        for (const Sampler& sampler : samplers())
            rows.push_back(measure(named, sampler, reference));
        if (argc > 3 && named.name == "seed") writeWhy(named.scene, reference, argv[3]);
        printScene(rows);
        for (const Row& r : rows)
            if (csv.is_open())
                csv << csvCell(r.scene) << ',' << r.sampler << ',' << csvCell(r.setting) << ','
                    << width << ',' << height << ',' << r.cameraRaysPerPixel << ','
                    << r.raysPerPixel << ',' << r.seconds << ',' << r.psnr << ',' << r.largest
                    << '\n';
    }
    return 0;
}
