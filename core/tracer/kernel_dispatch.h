// Which build of the tracing kernel runs (tracer_kernel.h): the widest
// instruction set this CPU supports (tuned for its cores where a kernel is),
// chosen once at the first trace, or the one the environment variable
// WHITTED_KERNEL names (baseline, sse4, avx2, avx2_zen, avx512, native) for
// tests and benchmarks.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace whitted {

struct TracerKernel;

// The kernel every trace runs in. Throws std::runtime_error, saying why and
// what this CPU can run, when WHITTED_KERNEL names a kernel that is unknown or
// that this CPU cannot run; a kernel the CPU lacks is never called.
const TracerKernel& activeKernel();

// The running kernel's name ("avx2"), for --stats and the About box.
std::string activeKernelName();
// The name with what it was compiled for: "avx2 (-march=x86-64-v3, 8 floats per packet)".
std::string activeKernelDescription();

// Kernels built into this program, widest first, and those of them this CPU runs.
std::vector<std::string> builtKernelNames();
std::vector<std::string> supportedKernelNames();
// The widest kernel this CPU runs (of two alike, the one tuned for its cores):
// what activeKernel() picks without WHITTED_KERNEL.
std::string widestSupportedKernelName();

// From now on trace with the named kernel (tests, benchmarks); an empty name
// goes back to the automatic choice. Throws std::runtime_error, as activeKernel()
// does, for a name that is unknown or that this CPU cannot run.
void useKernel(std::string_view name);

}  // namespace whitted
