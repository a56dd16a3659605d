// Work the user is not watching (a side comparison, a prediction) should
// yield the cores to the view's render and the GUI when they share them.
#pragma once

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace whitted {

// Nice 10 gives the calling thread about a tenth of a core's share against
// threads at 0; 19 would starve it whenever anything else runs (a build). On
// Linux a nice value belongs to a thread, and the threads it creates later
// (render()'s pool) inherit it. Elsewhere, nothing.
inline void lowerThisThreadsPriority() {
#ifdef __linux__
    constexpr int kNice = 10;
    setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), kNice);
#endif
}

}  // namespace whitted
