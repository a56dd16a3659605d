// One build of the hot tracing code: the entry points tracer.h declares, as
// compiled for one instruction set (core/tracer/tracer_kernel.cpp). kernel_dispatch.h
// picks one of them at start; tracer.cpp forwards every call to it.
#pragma once

#include <optional>

#include "tracer/tracer.h"

namespace whitted {

template <typename T>
struct KernelEntryPoints {
    std::optional<Hit<T>> (*closestHit)(const PreparedScene<T>&, const Ray<T>&, T tMax);
    Vec<T> (*traceRay)(const PreparedScene<T>&, const Ray<T>&, int depth, RayCounts&);
    void (*traceCameraSamples)(const PreparedScene<T>&, const CameraSample<T>*, int count,
                               Vec<T>* radiance, RayCounts&);
    void (*traceCameraRows)(const PreparedScene<T>&, int y, int rows, int x0, int count, int n,
                            Vec<T>* radiance, RayCounts&);
    void (*traceCameraRowAtDepths)(const PreparedScene<T>&, int y, int x0, int count, int n,
                                   Vec<T>* radiance, const int* depths, int depthCount,
                                   Vec<T>* atDepths, RayCounts&);
    void (*traceCameraBlock)(const PreparedScene<T>&, int y, int x0, int pixels, int n0,
                             int samples, Vec<T>* radiance, RayCounts&);
};

struct TracerKernel {
    const char*
        name;  // "avx512", "avx2", "avx2_zen", "sse4", "baseline", "native" (the build's flags)
    const char* isa;   // the -march it was compiled with ("native": the build's flags)
    const char* tune;  // and the -mtune: "generic", or a core family ("znver3")
    int vectorBytes;   // size of one packet vector: 16 floats per packet at 64
    KernelEntryPoints<float> floats;
    KernelEntryPoints<double> doubles;

    template <typename T>
    const KernelEntryPoints<T>& entryPoints() const {
        if constexpr (sizeof(T) == sizeof(float))
            return floats;
        else
            return doubles;
    }
};

}  // namespace whitted
