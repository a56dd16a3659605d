// The CPU time the calling thread has used. Unlike the wall clock, it does not
// run while the thread waits for a core that another program (or the
// editor's own view render) holds, so timings made on a busy machine still
// say what the work costs.
#pragma once

#include <ctime>

namespace whitted {

inline double threadCpuSeconds() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
}

}  // namespace whitted
