#include "tracer/kernel_dispatch.h"

#include <atomic>
#include <cstdlib>
#include <stdexcept>

#include "tracer/tracer_kernel.h"

// Each kernel object (tracer_kernel.cpp built per instruction set) defines its
// table in its own namespace.
namespace whitted {
#ifdef WHITTED_KERNEL_NATIVE
namespace isa_build {
extern const TracerKernel kTracerKernel;
}
#endif
namespace isa_avx512 {
extern const TracerKernel kTracerKernel;
}
namespace isa_avx2_zen {
extern const TracerKernel kTracerKernel;
}
namespace isa_avx2 {
extern const TracerKernel kTracerKernel;
}
namespace isa_sse4 {
extern const TracerKernel kTracerKernel;
}
namespace isa_baseline {
extern const TracerKernel kTracerKernel;
}
}  // namespace whitted

namespace whitted {

namespace {

// Widest first: the first one the CPU runs, and is tuned for, is the default.
constexpr const TracerKernel* kBuiltKernels[] = {
#ifdef WHITTED_KERNEL_NATIVE
    &isa_build::kTracerKernel,
#endif
    &isa_avx512::kTracerKernel, &isa_avx2_zen::kTracerKernel, &isa_avx2::kTracerKernel,
    &isa_sse4::kTracerKernel,   &isa_baseline::kTracerKernel,
};

// This file is built with the project's flags, never a kernel's, so it can ask
// on any x86-64 CPU. The levels include the OS's saving of the wide registers.
bool cpuRuns(const TracerKernel& kernel) {
    __builtin_cpu_init();
    const std::string_view isa = kernel.isa;
    if (isa == "x86-64-v4") return __builtin_cpu_supports("x86-64-v4");
    if (isa == "x86-64-v3") return __builtin_cpu_supports("x86-64-v3");
    if (isa == "x86-64-v2") return __builtin_cpu_supports("x86-64-v2");
    return true;  // x86-64 itself, or "native": the flags this program already needs
}

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& name : names) out += (out.empty() ? "" : ", ") + name;
    return out;
}

// A kernel tuned for one vendor's cores is the default on those alone.
bool tunedForThisCpu(const TracerKernel& kernel) {
    if (std::string_view(kernel.tune).starts_with("znver")) return __builtin_cpu_is("amd");
    return true;
}

const TracerKernel& widestSupported() {
    for (const TracerKernel* kernel : kBuiltKernels)
        if (cpuRuns(*kernel) && tunedForThisCpu(*kernel)) return *kernel;
    return isa_baseline::kTracerKernel;  // not reached: every x86-64 CPU runs it
}

const TracerKernel& kernelNamed(std::string_view name) {
    for (const TracerKernel* kernel : kBuiltKernels) {
        if (name != kernel->name) continue;
        if (!cpuRuns(*kernel))
            throw std::runtime_error(
                "tracer kernel \"" + std::string(name) + "\" needs " + kernel->isa +
                ", which this CPU lacks; it runs: " + joined(supportedKernelNames()));
        return *kernel;
    }
    throw std::runtime_error("no tracer kernel is named \"" + std::string(name) +
                             "\"; this build has: " + joined(builtKernelNames()));
}

// WHITTED_KERNEL if set, else the widest.
const TracerKernel& automaticChoice() {
    const char* requested = std::getenv("WHITTED_KERNEL");
    if (requested && *requested) {
        try {
            return kernelNamed(requested);
        } catch (const std::runtime_error& e) {
            throw std::runtime_error(std::string("WHITTED_KERNEL: ") + e.what());
        }
    }
    return widestSupported();
}

std::atomic<const TracerKernel*> active{nullptr};

}  // namespace

const TracerKernel& activeKernel() {
    if (const TracerKernel* kernel = active.load(std::memory_order_acquire)) return *kernel;
    // Threads racing here all store the same choice.
    const TracerKernel& chosen = automaticChoice();
    active.store(&chosen, std::memory_order_release);
    return chosen;
}

std::string activeKernelName() {
    return activeKernel().name;
}

std::string activeKernelDescription() {
    const TracerKernel& kernel = activeKernel();
    const std::string tune =
        std::string_view(kernel.tune) == "generic" ? "" : std::string(" -mtune=") + kernel.tune;
    return std::string(kernel.name) + " (-march=" + kernel.isa + tune + ", " +
           std::to_string(kernel.vectorBytes / sizeof(float)) + " floats per packet)";
}

std::vector<std::string> builtKernelNames() {
    std::vector<std::string> names;
    for (const TracerKernel* kernel : kBuiltKernels) names.emplace_back(kernel->name);
    return names;
}

std::vector<std::string> supportedKernelNames() {
    std::vector<std::string> names;
    for (const TracerKernel* kernel : kBuiltKernels)
        if (cpuRuns(*kernel)) names.emplace_back(kernel->name);
    return names;
}

std::string widestSupportedKernelName() {
    return widestSupported().name;
}

void useKernel(std::string_view name) {
    active.store(name.empty() ? &automaticChoice() : &kernelNamed(name), std::memory_order_release);
}

}  // namespace whitted
