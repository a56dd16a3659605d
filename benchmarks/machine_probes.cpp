#include "machine_probes.h"

#include <immintrin.h>
#include <sys/mman.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <functional>
#include <thread>
#include <vector>

namespace whitted::bench {

namespace {

// Results land here so that the compiler keeps the work.
volatile std::uint64_t sink;

void dependentMultiplies() {
    std::uint64_t x = 12345;
    for (long k = 0; k < 400'000'000; ++k) x = x * 6364136223846793005ULL + 1442695040888963407ULL;
    sink = x;
}

// Ten independent chains of fused multiply-adds: more than the units'
// latency times their number, so the units, not the chains, bound the rate.
// Compiled for AVX2 and FMA whatever the build's target; run only where the
// CPU has them (probeMachine()).
__attribute__((target("avx2,fma"))) void vectorMultiplyAdds() {
    __m256 a[10];
    for (int i = 0; i < 10; ++i) a[i] = _mm256_set1_ps(1.0f + 0.1f * float(i));
    const __m256 m = _mm256_set1_ps(0.9999999f), c = _mm256_set1_ps(1e-7f);
    for (long k = 0; k < 300'000'000; ++k) {
#pragma GCC unroll 10
        for (int i = 0; i < 10; ++i) a[i] = _mm256_fmadd_ps(a[i], m, c);
    }
    __m256 total = a[0];
    for (int i = 1; i < 10; ++i) total = _mm256_add_ps(total, a[i]);
    float lanes[8];
    _mm256_storeu_ps(lanes, total);
    float sum = 0;
    for (const float lane : lanes) sum += lane;
    sink = static_cast<std::uint64_t>(sum);
}

// Each thread reads its own buffer, written once before the clock starts.
std::function<void()> memoryReads(std::vector<std::uint64_t>& buffer) {
    return [&buffer] {
        std::uint64_t total = 0;
        for (int pass = 0; pass < 4; ++pass)
            for (const std::uint64_t w : buffer) total += w;
        sink = total;
    };
}

void pageFirstTouches() {
    constexpr std::size_t kBytes = std::size_t(256) << 20;
    void* p = mmap(nullptr, kBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) return;
    char* bytes = static_cast<char*>(p);
    for (std::size_t i = 0; i < kBytes; i += 4096) bytes[i] = 1;
    munmap(p, kBytes);
}

double msToRun(const std::vector<std::function<void()>>& work) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::thread> threads;
    for (const auto& w : work) threads.emplace_back(w);
    for (std::thread& t : threads) t.join();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

// One thread and two in turn, `runs` times each: the fastest of each.
ProbeResult probe(const char* name, const std::function<void()>& first,
                  const std::function<void()>& second, int runs) {
    ProbeResult r{name, 1e300, 1e300};
    for (int i = 0; i < runs; ++i) {
        r.oneThreadMs = std::min(r.oneThreadMs, msToRun({first}));
        r.twoThreadsMs = std::min(r.twoThreadsMs, msToRun({first, second}));
    }
    return r;
}

}  // namespace

std::vector<ProbeResult> probeMachine(int runs) {
    std::vector<ProbeResult> results;
    results.push_back(
        probe("dependent integer multiplies", dependentMultiplies, dependentMultiplies, runs));
    if (__builtin_cpu_supports("fma"))
        results.push_back(
            probe("fused multiply-adds (256-bit)", vectorMultiplyAdds, vectorMultiplyAdds, runs));
    {
        constexpr std::size_t kWords = std::size_t(512) << 17;  // 512 MB
        std::vector<std::uint64_t> a(kWords, 1), b(kWords, 2);
        results.push_back(
            probe("memory reads (512 MB a thread)", memoryReads(a), memoryReads(b), runs));
    }
    results.push_back(probe("first writes to new pages (256 MB a thread)", pageFirstTouches,
                            pageFirstTouches, runs));
    return results;
}

}  // namespace whitted::bench
