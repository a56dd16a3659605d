// Work spread over threads for the passes over every sphere (the tree's build,
// refit and leaf copies, the scene's preparation): plain std::thread, started
// per call. Each index's work must touch only what belongs to that index, so
// that the result is the same for any number of threads.
#pragma once

#include <sched.h>

#include <algorithm>
#include <atomic>
#include <numeric>
#include <thread>
#include <vector>

namespace whitted {

// A bound for the whole process on the threads of work that asks for no
// count: reading a scene, writing an image, the analyses, a render whose
// options leave it at 0. whitted-render sets it from --threads, so that the
// flag bounds all of the program's work, not the render's alone. 0: none.
inline std::atomic<int> processThreadLimit{0};

// The number of threads for `requested` (0: all cores, or processThreadLimit
// if fewer), as render() and the passes over every sphere use it. All the
// cores this process may run on: a Slurm task or `taskset` confines it to
// some of the machine's, and std::thread::hardware_concurrency() counts them
// all, so a task given two cores of a 64-core node would start 64 threads.
inline int resolveThreadCount(int requested) {
    if (requested > 0) return requested;
    // Asked once: planning a render asks for each of its small probes.
    static const int cores = [] {
        cpu_set_t allowed;
        if (sched_getaffinity(0, sizeof allowed, &allowed) == 0)
            return std::max(1, CPU_COUNT(&allowed));
        return int(std::max(1u, std::thread::hardware_concurrency()));
    }();
    const int limit = processThreadLimit.load(std::memory_order_relaxed);
    return limit > 0 ? std::min(limit, cores) : cores;
}

// Spheres per task of a pass over every sphere: enough work per task that
// handing it out is nothing beside it.
inline constexpr int kSphereChunk = 1 << 14;

// Runs work(i) for each i of `order`, handed out in that order (put the
// longest first) to up to `threads` threads, this one included. A single
// item runs here, with no thread started.
template <typename Work>
void parallelFor(const std::vector<int>& order, int threads, const Work& work) {
    std::atomic<std::size_t> next{0};
    const auto run = [&] {
        for (std::size_t k; (k = next++) < order.size();) work(order[k]);
    };
    std::vector<std::thread> helpers;
    for (int i = 1; i < std::min<int>(threads, static_cast<int>(order.size())); ++i)
        helpers.emplace_back(run);
    run();
    for (std::thread& h : helpers) h.join();
}

// The number of chunks forEachChunk() cuts `count` items into.
inline int chunkCount(int count, int chunk = kSphereChunk) {
    return (count + chunk - 1) / chunk;
}

// Runs work(c, begin, end) for each chunk c, the items [begin, end) of
// [0, count), `chunk` items a chunk, on up to `threads` threads: for passes
// that keep something per chunk (a partial sum, a place to write from).
template <typename Work>
void forEachChunk(int count, int threads, const Work& work, int chunk = kSphereChunk) {
    std::vector<int> chunks(chunkCount(count, chunk));
    std::iota(chunks.begin(), chunks.end(), 0);
    parallelFor(chunks, threads,
                [&](int c) { work(c, c * chunk, std::min(count, (c + 1) * chunk)); });
}

// Runs work(i) for i in [0, count), in chunks of `chunk` on up to `threads`
// threads.
template <typename Work>
void forChunks(int count, int threads, const Work& work, int chunk = kSphereChunk) {
    forEachChunk(
        count, threads,
        [&](int, int begin, int end) {
            for (int i = begin; i < end; ++i) work(i);
        },
        chunk);
}

}  // namespace whitted
