// What an adaptive pass of a render to Preview or Final costs besides its
// rays (docs/design/performance.md), on a
// 640x480 picture, the size the shipped scenes are saved at:
//   BM_UnseenLargest     unseenLargest() over every 16x16 tile: what one more
//                        sample of each pixel's most different neighbour
//                        would change
//   BM_HalvesEstimate    halvesEstimate() over every row: each pixel's error
//                        from the two halves of its samples
//   BM_SrgbFastRow       srgbEncodeFast() over the picture's values, which
//                        both of them take their codes from
// Run: build/bin/bench_estimates --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "image/srgb.h"
#include "tracer/adaptive_sampling.h"

namespace {

using namespace whitted;

constexpr int kWidth = 640, kHeight = 480;

// Noise over a dark-weighted range, as renders are, so that no
// neighbourhood is flat and every pixel pays for its codes.
Image noisyPicture(unsigned seed) {
    Image image(kWidth, kHeight);
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> value(0.0f, 1.0f);
    for (float& v : image.rgb) v = value(random) * value(random);
    return image;
}

void BM_UnseenLargest(benchmark::State& state) {
    const Image image = noisyPicture(1);
    PixelLargest pixels;
    pixels.width = kWidth, pixels.height = kHeight;
    pixels.codes.assign(std::size_t(kWidth) * kHeight, 0.0f);
    const PixelRect whole{0, 0, kWidth, kHeight};
    for (auto _ : state) {
        double largest = 0.0;
        for (int y = 0; y < kHeight; y += kAdaptiveTileEdge)
            for (int x = 0; x < kWidth; x += kAdaptiveTileEdge)
                largest += unseenLargest(image, {x, y, kAdaptiveTileEdge, kAdaptiveTileEdge}, whole,
                                         8, pixels);
        benchmark::DoNotOptimize(largest);
    }
    state.SetItemsProcessed(state.iterations() * std::int64_t(kWidth) * kHeight);
}
BENCHMARK(BM_UnseenLargest)->Unit(benchmark::kMillisecond);

void BM_HalvesEstimate(benchmark::State& state) {
    const Image before = noisyPicture(1), after = noisyPicture(2);
    std::vector<float> largest(std::size_t(kWidth) * kHeight);
    for (auto _ : state) {
        double mse = 0.0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; x += kAdaptiveTileEdge)
                mse += halvesEstimate(before.pixel(x, y), after.pixel(x, y), kAdaptiveTileEdge,
                                      &largest[std::size_t(y) * kWidth + x])
                           .mse();
        benchmark::DoNotOptimize(mse);
    }
    state.SetItemsProcessed(state.iterations() * std::int64_t(kWidth) * kHeight);
}
BENCHMARK(BM_HalvesEstimate)->Unit(benchmark::kMillisecond);

void BM_SrgbFastRow(benchmark::State& state) {
    const Image image = noisyPicture(1);
    std::vector<float> encoded(image.rgb.size());
    for (auto _ : state) {
        srgbEncodeFast(image.rgb.data(), image.rgb.size(), encoded.data());
        benchmark::DoNotOptimize(encoded.data());
    }
    state.SetItemsProcessed(state.iterations() * std::int64_t(image.rgb.size()));
}
BENCHMARK(BM_SrgbFastRow)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
